"""seaecho.processing stage."""
