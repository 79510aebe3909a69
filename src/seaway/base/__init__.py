"""The base layer: units and constants, spherical geometry, file helpers (atomic writes, NetCDF
checks), validation of numbers, interruptible searches and smooth random fields. Imports nothing
of seaway but the compiled core."""
