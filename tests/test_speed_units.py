"""What speed-in-knots reads as a speed and its unit: the names of variables, the
names of MOOS variables, and conversion factors, each only where it says one thing."""

from __future__ import annotations

import pytest

from moos_lint.frontends.cpp.angle_exprs import is_speed_var
from moos_lint.frontends.cpp.values import AbstractValue, settle, speed_name_unit


@pytest.mark.parametrize(
    ("name", "unit"),
    [
        ("dbl_kts", "kn"),
        ("m_speed_kts", "kn"),
        ("dSpeedKnots", "kn"),
        ("rmcdata.m_dSpeedKnots", "kn"),
        ("sogKts", "kn"),
        ("SOG_KTS", "kn"),
        ("sog_kn", "kn"),
        ("speed_kmh", "km/h"),
        ("m_kph", "km/h"),
        ("wind_mph", "mph"),
        # silent
        ("m_kn", None),
        ("kn_gain", None),
        ("m_speed", None),
        ("dbl_mps", None),
        ("knotted_rope", None),
    ],
)
def test_speed_name_unit(name, unit):
    assert speed_name_unit(name) == unit


@pytest.mark.parametrize(
    ("name", "speed"),
    [
        ("NAV_SPEED", True),
        ("GPS_SOG", True),
        ("DESIRED_SPEED", True),
        ("WATER_STW", True),
        ("SPEED_KNOTS", False),
        ("GPS_SPEED_KTS", False),
        ("NAV_SPEED_OVER", False),
        ("MAX_SPEED_MPH", False),
        ("NAV_HEADING", False),
    ],
)
def test_is_speed_var(name, speed):
    assert is_speed_var(name) is speed


@pytest.mark.parametrize(
    ("unit", "factor", "out"),
    [
        ("kn", 0.514444, "m/s"),
        ("kn", 1 / 1.94384, "m/s"),
        ("kn", 0.5144, "m/s"),  # written with four digits
        ("km/h", 1 / 3.6, "m/s"),
        ("mph", 0.44704, "m/s"),
        ("kn", 0.5, None),  # another factor: nothing known
        ("km/h", 2.77778, None),  # km/h times 2.78 is no unit
        (None, 1.94384, "kn"),
        (None, 2.23694, "mph"),
        (None, 3.6, None),  # 3.6 is km/h only from metres per second
        ("m/s", 3.6, "km/h"),
        ("deg", 1.94384, None),  # an angle is never a speed
    ],
)
def test_conversion_factors(unit, factor, out):
    v = AbstractValue(unit=unit, scale=factor, why=("source",))
    assert settle(v).unit == out
