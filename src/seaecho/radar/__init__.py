"""seaecho.radar stage."""
