"""Vessel files (seaway.vessel.load): the shipped examples with a source or an assumption for
every value, and wrong files refused naming the field and the fix."""

from __future__ import annotations

import json

import pytest

from seaway.vessel import EXAMPLES, VesselFileError, load
from seaway.vessel.profile import FIELDS, example_path


@pytest.mark.parametrize("name", EXAMPLES)
def test_every_value_of_a_shipped_example_has_its_source_or_is_an_assumption(name):
    import tomllib

    with open(example_path(name), "rb") as f:
        raw = tomllib.load(f)
    given = set(raw) - {"sources"}
    assert given <= set(raw["sources"]) and set(raw["sources"]) <= given
    for key, text in raw["sources"].items():
        assert text.startswith("assumption") or any(
            w in text
            for w in ("Sotnikova 2009", "Olovyannikov 2025", "CHNL Information Office, 2017", "Polar Record")
        ), (key, text)
    profile = load(name)
    assert profile.path == f"{name} (shipped with seaway)" and profile.vessel.check(waves=False) is None


def test_the_examples_carry_their_sources_values():
    arc7 = load("arc7-lng-carrier")
    assert (arc7.ice_class, arc7.draft_m, arc7.vessel.speed_kn, arc7.vessel.length_m, arc7.vessel.beam_m) == (
        "Arc7",
        11.8,
        19.5,
        299.0,
        50.0,
    )  # CHNL Information Office (2017)
    ship = load("sotnikova-container-ship")
    assert ship.vessel.displacement_t == 40000.0 and ship.speed_range_kn == (5.0, 24.0)  # Sotnikova 2009
    assert ship.vessel.danger_wind_ms == 11.0 and ship.ice_class is None
    # The fuel curve from its reference point: the propeller law at 1-kn settings from 5 to 24 kn.
    assert (
        ship.fuel_speeds_kn[0] == 5.0 and ship.fuel_speeds_kn[-1] == 24.0 and len(ship.fuel_speeds_kn) == 20
    )
    assert ship.fuel_rates_t_per_h[15] == pytest.approx(3.0)  # 20 kn: the reference rate
    assert ship.fuel_rates_t_per_h[-1] == pytest.approx(3.0 * (24 / 20) ** 3)
    pc6 = load("pc6-general-cargo")
    assert pc6.ice_class == "PC6" and "draft_m" in pc6.assumed and pc6.vessel.speed_loss == "khokhlov"


def _write(tmp_path, text, name="ship.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


@pytest.mark.parametrize(
    "text, message",
    [
        (
            'name = "x"\nservice_speed_kn = 12\ndraught_m = 9',
            r"unknown field 'draught_m' \(did you mean draft_m\?\); the fields are name, ",
        ),
        (
            'name = "x"\nservice_speed_kn = "fast"',
            r"service_speed_kn \(calm-water service speed in knots\) must be a positive number, got 'fast'; e\.g\. service_speed_kn = 19\.5",
        ),
        ('name = "x"\nservice_speed_kn = -3', r"service_speed_kn .* must be a positive number, got -3"),
        ('name = "x"', r"service_speed_kn .* is missing; e\.g\. service_speed_kn = 19\.5"),
        (
            'name = "x"\nservice_speed_kn = 12\nice_class = "Arc12"',
            r"ice_class .* is not an ice class seaway knows",
        ),
        (
            'name = "x"\nservice_speed_kn = 12\nspeed_range_kn = [14, 6]',
            r"speed_range_kn .* must be \[slowest, fastest\], got \[14\.0, 6\.0\]",
        ),
        (
            'name = "x"\nservice_speed_kn = 12\nspeed_loss = "holtrop"',
            r"speed_loss .* must be one of none, khokhlov, stawave1, got 'holtrop'",
        ),
        (
            'name = "x"\nservice_speed_kn = 12\nspeed_loss = "stawave1"',
            r"speed_loss .* = 'stawave1' needs beam_m, length_m and calm_resistance_kn",
        ),
        (
            'name = "x"\nservice_speed_kn = 12\n[fuel]\nspeeds_kn = [10, 12]\nrates_t_per_h = [1]',
            r"fuel .* needs speeds_kn and rates_t_per_h, two lists of one length",
        ),
        (
            'name = "x"\nservice_speed_kn = 12\n[sources]\ndraught_m = "yard"',
            r"sources .* must be a table of the file's fields, got \['draught_m'\]",
        ),
        ('name = "x"\nservice_speed_kn = 12 kn', r"not valid TOML \("),
        (
            'name = "x"\nservice_speed_kn = 12\noutside_validity = "ignore"',
            r"outside_validity .* must be refuse or warn, got 'ignore'",
        ),
    ],
)
def test_a_wrong_vessel_file_is_refused_naming_the_field_and_the_fix(tmp_path, text, message):
    path = _write(tmp_path, text)
    with pytest.raises(VesselFileError, match=rf"vessel file {path}: {message}"):
        load(path)


def test_json_vessel_files_and_missing_files(tmp_path):
    path = _write(
        tmp_path,
        json.dumps(
            {
                "name": "Ice3 tanker",
                "ice_class": "Ice3",
                "service_speed_kn": 13,
                "fuel": {"speeds_kn": [10, 13], "rates_t_per_h": [0.8, 1.6]},
            }
        ),
        "s.json",
    )
    p = load(path)
    assert (p.name, p.ice_class, p.vessel.speed_kn, p.fuel_rates_t_per_h) == (
        "Ice3 tanker",
        "Ice3",
        13.0,
        (0.8, 1.6),
    )
    with pytest.raises(
        VesselFileError, match=r"no such file \(the examples shipped with seaway: arc7-lng-carrier, "
    ):
        load(tmp_path / "none.toml")
    assert set(FIELDS) >= {
        "name",
        "ice_class",
        "draft_m",
        "ukc_m",
        "service_speed_kn",
        "speed_range_kn",
        "displacement_t",
        "length_m",
        "fuel",
        "max_wind_ms",
        "max_wave_m",
    }


@pytest.mark.parametrize(
    "field, value, message",
    [
        (
            "beam_m",
            "1e30",
            r"beam_m .* must be between 1 and 80 \(the widest ship afloat, the Prelude FLNG, is 74 m",
        ),
        ("displacement_t", "1e30", r"displacement_t .* must be between 10 and 700000 \(Seawise Giant"),
        ("length_m", "1e30", r"length_m .* must be between 5 and 500 \(Seawise Giant"),
        ("draft_m", "1" + "0" * 400, r"draft_m .* must be a positive number, got 1000"),
        ("max_wave_m", "inf", r"max_wave_m .* must be a positive number, got inf"),
        ("ukc_m", "nan", r"ukc_m .* must be a non-negative number, got nan"),
    ],
)
def test_implausible_sizes_are_refused_with_the_range_and_its_source(tmp_path, field, value, message):
    """Issue 27: load() accepted a 1e30 m beam or a 1e30 t displacement; every number has a
    plausible range (RANGES) with the record it comes from. An integer too large for a float
    raised OverflowError."""
    path = _write(tmp_path, f'name = "x"\nservice_speed_kn = 12\n{field} = {value}')
    with pytest.raises(VesselFileError, match=rf"vessel file {path}: {message}"):
        load(path)


def test_every_number_field_has_a_range_with_its_source():
    from seaway.vessel.profile import RANGES

    numbers = {k for k, (kind, _, _) in FIELDS.items() if kind in ("positive", "non-negative", "range")}
    assert numbers <= set(RANGES)
    for lo, hi, why in RANGES.values():
        assert 0 <= lo < hi < 1e7 and len(why) > 10
