"""seaecho.ocean stage."""
