"""seaecho.tracing stage."""
