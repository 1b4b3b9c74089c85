"""seaecho.wake stage."""
