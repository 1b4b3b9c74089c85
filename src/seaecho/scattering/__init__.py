"""seaecho.scattering stage."""
