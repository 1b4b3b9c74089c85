"""seaecho.io stage."""
