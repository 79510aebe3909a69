"""The roles a forecast's fields play, one table: for each role the CF standard names that say
it (first preferred), the GRIB short names cfgrib gives it (ECMWF parameter database), the code
numbers CDO writes for it as varNNN (a hint only: a code number alone does not say its table),
and the names users write for it. Every reader and message takes its names from here."""

from __future__ import annotations

from typing import NamedTuple


class Role(NamedTuple):
    standard_names: tuple[str, ...]
    grib: tuple[str, ...] = ()
    cdo: tuple[tuple[str, str], ...] = ()  # (varNNN, its meaning in its table)
    aliases: tuple[str, ...] = ()


#: role -> its names; the order of the roles is the order they are listed in messages.
TABLE: dict[str, Role] = {
    "current_east": Role(
        (
            "eastward_sea_water_velocity",
            "surface_eastward_sea_water_velocity",
            "barotropic_eastward_sea_water_velocity",
        ),
        ("uo", "ocu", "uogrd"),
        aliases=("current_u",),
    ),
    "current_north": Role(
        (
            "northward_sea_water_velocity",
            "surface_northward_sea_water_velocity",
            "barotropic_northward_sea_water_velocity",
        ),
        ("vo", "ocv", "vogrd"),
        aliases=("current_v",),
    ),
    "wave_height": Role(
        ("sea_surface_wave_significant_height",),
        ("swh", "htsgw"),
        (("var229", "table 140: significant height of wind waves and swell"),),
        ("hs", "swh", "significant_wave_height"),
    ),
    "wave_from": Role(
        ("sea_surface_wave_from_direction",),
        ("mwd",),
        (("var230", "table 140: mean wave direction"),),
        ("wave_direction", "wave_dir", "mean_wave_direction", "wave_to"),
    ),
    "wave_period": Role(
        (
            "sea_surface_wave_mean_period",
            "sea_surface_wave_mean_period_from_variance_spectral_density_first_frequency_moment",
            "sea_surface_wave_period_at_variance_spectral_density_maximum",
        ),
        ("mwp", "pp1d"),
        (("var232", "table 140: mean wave period"),),
        ("mean_wave_period",),
    ),
    "wind_east": Role(
        ("eastward_wind",), ("u10", "10u"), (("var165", "table 128: 10 m eastward wind"),), ("u10", "wind_u")
    ),
    "wind_north": Role(
        ("northward_wind",),
        ("v10", "10v"),
        (("var166", "table 128: 10 m northward wind"),),
        ("v10", "wind_v"),
    ),
    "wind_speed": Role(("wind_speed",), ("si10", "ws10"), (("var207", "table 128: 10 m wind speed"),)),
    # the ice (ICE_ROLES), priced with the currents by seaway.voyage.forecastice
    "ice_concentration": Role(
        ("sea_ice_area_fraction",),
        ("ci", "siconc", "icec"),
        (("var31", "table 128: sea-ice cover (fraction)"), ("var91", "WMO table 2: ice cover (proportion)")),
    ),
    "ice_thickness": Role(
        ("sea_ice_thickness",), ("sithick", "sit", "icetk"), (("var92", "WMO table 2: ice thickness (m)"),)
    ),
}
#: Roles that are the ice of a coupled ice-ocean forecast (HYCOM-CICE, TOPAZ, ROMS), not its weather.
ICE_ROLES = ("ice_concentration", "ice_thickness")
#: CDO code numbers of fields that play no role (said in the hint, so nobody maps them).
NO_ROLE_CDO = {
    "var95": "WMO table 2: u-component of ice drift (not a role: seaway does not price the drift)",
    "var96": "WMO table 2: v-component of ice drift (not a role: seaway does not price the drift)",
}

ROLES = tuple(TABLE)
STANDARD_NAMES = {r: t.standard_names for r, t in TABLE.items()}
GRIB_NAMES = {r: t.grib for r, t in TABLE.items()}
CDO_CODES: dict[str, tuple[str | None, str]] = {
    **{code: (r, what) for r, t in TABLE.items() for code, what in t.cdo},
    **{code: (None, what) for code, what in NO_ROLE_CDO.items()},
}
ALIASES = {a: r for r, t in TABLE.items() for a in t.aliases}
