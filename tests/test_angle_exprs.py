"""How a published angle is read as one angle in one of two units (``angle_conversion``),
which yaw-heading-sign compares between a yaw and a heading of one function."""

from __future__ import annotations

import pytest

from moos_lint.frontends.cpp.angle_exprs import angle_conversion


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        ("r.euler.get_scaled(2)", (1, "r.euler.get_scaled(2)", None)),
        ("angle360(((e * 180 / 3.14159)))", (1, "e", "deg")),
        ("fabs(h / 100.0) * (PI / 180.0)", (1, "fabs(h/100.0)", "rad")),
        ("PI/180.0*atof(s)", (1, "atof(s)", "rad")),
        ("h / 180 * M_PI", (1, "h", "rad")),
        ("MOOS_ANGLE_WRAP(-h * M_PI / 180)", (-1, "h", "rad")),
        ("((4*atan(1)) / -180.0) * field", (-1, "field", "rad")),
        ("-(angle360(h * 180 / M_PI))", (-1, "h", "deg")),
        ("-MOOSRad2Deg(a + b)", (-1, "a+b", "deg")),
        ("degToRadians(angle180(hdg))", (1, "hdg", "rad")),
        ("p->yaw * 57.2958", (1, "p->yaw", "deg")),
        ("atan2(dx, dy) * 180 / M_PI", (1, "atan2(dx,dy)", "deg")),
        # not one angle times a conversion: the expression as it is
        ("a - b * 180 / M_PI", (1, "a-b*180/M_PI", None)),
        ("x * y * M_PI / 180", (1, "x*y*M_PI/180", None)),
        ("h * 2", (1, "h*2", None)),
        ("(90 - h) * M_PI / 180", (1, "90-h", "rad")),
    ],
)
def test_angle_conversion(expr, expected):
    assert angle_conversion(expr) == expected
