"""Datasets (netCDF via xarray/h5netcdf, written atomically) and figures."""
