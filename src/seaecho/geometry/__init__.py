"""seaecho.geometry stage."""
