"""What a variable's name says it holds, as geodesy-argument-order and the frame of
``atan2`` read it: a name that says nothing, or two things, is never judged."""

from __future__ import annotations

import pytest

from moos_lint.frontends.cpp.declarations import parameter_names
from moos_lint.frontends.cpp.names import axis_of, displacement_axis
from moos_lint.semantics.cpp_checks import differs_from_geodesy


@pytest.mark.parametrize(
    ("expression", "axis"),
    [
        ("nav_x", "east"),
        ("xUTM", "east"),
        ("dfXLocal", "east"),
        ("lx", "east"),
        ("record.getX()", "east"),
        ("TargetEastings", "east"),
        ("m_position.y", "north"),
        ("ypos_d", "north"),
        ("dfNLocal", "north"),
        ("meters_n[j][i]", "north"),
        ("y1", "north"),
        ("GpsLat", "lat"),
        ("msg.nav().lat()", "lat"),
        ("m_dLongitude", "lon"),
        ("msg->position.lng_deg", "lon"),
        # silent: no axis word, or two
        ("m_max", None),
        ("tmp", None),
        ("n_x", None),
        ("latlon_vec[0]", None),
        ("m_lat_north", None),
        ("pointLatLong", None),
        ("0.0", None),
    ],
)
def test_axis_of(expression, axis):
    assert axis_of(expression) == axis


def test_own_declarations_found_by_name(tmp_path):
    header = tmp_path / "Projection.h"
    header.write_text(
        "class P {\n"
        "  void LatLong2LocalUTM(double Lat, double Lon, double &x, double &y);\n"
        "  bool LocalGrid2LatLong(double dfEast, double dfNorth, double &dfLat,\n"
        "                         double &dfLon);\n"
        "};\n"
        "void f() { p.LatLong2LocalUTM(lat, lon, y, x); }\n"
    )
    found = parameter_names(
        ["LatLong2LocalUTM", "LocalGrid2LatLong"], [str(header)], lambda p: header.read_bytes()
    )
    assert found == {
        "LatLong2LocalUTM": [["Lat", "Lon", "x", "y"]],
        "LocalGrid2LatLong": [["dfEast", "dfNorth", "dfLat", "dfLon"]],
    }
    assert differs_from_geodesy("LatLong2LocalUTM", ["Lat", "Lon", "x", "y"])
    assert not differs_from_geodesy("LocalGrid2LatLong", ["dfEast", "dfNorth", "dfLat", "dfLon"])
    stock = ["lat", "lon", "MetersNorth", "MetersEast"]
    assert not differs_from_geodesy("LatLong2LocalGrid", stock)


@pytest.mark.parametrize(
    ("expression", "axis"),
    [
        ("m_curY_R - m_curY_L", "north"),
        ("(dlb_x - m_nav_x_start_rot)", "east"),
        ("a->y - b->y", "north"),
        ("path.back().m_y - point_set.back().m_y", "north"),
        ("dx", "east"),
        ("delta_y", "north"),
        ("dis_y", "north"),
        # a coordinate alone, or a magnetometer's field: its frame is not told by its name
        ("y", None),
        ("mag_y", None),
        ("m_vy", None),
        ("sin(a)", None),
        ("-dy", None),
        ("m_x - m_prev_y", None),
        ("x1 - x0 + 1", None),
    ],
)
def test_displacement_axis(expression, axis):
    assert displacement_axis(expression) == axis
