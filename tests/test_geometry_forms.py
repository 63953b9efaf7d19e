"""The geometry-form port agrees with MOOS-IvP's own parsers.

Each verdict below was produced by the real ``string2Poly``, ``string2SegList``
and ``string2Point`` (moos-ivp a2a9b716, ``lib_geometry`` + ``lib_mbutil``
compiled with g++): ``convex_polygon`` is ``string2Poly(v).is_convex()``,
``waypoints`` is BHV_Waypoint's ``empty``/``start`` or a non-empty
``string2SegList(v)`` or ``string2Poly(v)``, ``point`` is
``string2Point(v).valid()``.
"""

import pytest

from moos_lint.rules.mission.invalid_parameter_value import problem
from moos_lint.semantics.geometry_forms import INVALID, UNKNOWN, VALID, judge

V, X = VALID, INVALID

#: (form, value, verdict of the C++ parser)
AGREED = [
    ("convex_polygon", "", X),
    ("waypoints", "", X),
    ("point", "", X),
    ("convex_polygon", " x = 1 , y = 2 ", X),
    ("waypoints", " x = 1 , y = 2 ", X),
    ("point", " x = 1 , y = 2 ", V),
    ("convex_polygon", "+-5,0:10,0:10,10", V),
    ("waypoints", "+-5,0:10,0:10,10", V),
    ("point", "+-5,0:10,0:10,10", V),
    ("convex_polygon", "- 5,3", X),
    ("waypoints", "- 5,3", X),
    ("point", "- 5,3", X),
    ("convex_polygon", "--5,0:10,0:10,10", V),
    ("waypoints", "--5,0:10,0:10,10", V),
    ("point", "--5,0:10,0:10,10", V),
    ("convex_polygon", "-1,-1:1,-1:1,1:-1,1", V),
    ("waypoints", "-1,-1:1,-1:1,1:-1,1", V),
    ("point", "-1,-1:1,-1:1,1:-1,1", V),
    ("convex_polygon", "-10.5,3.25:20,-7.5:+5,40", V),
    ("waypoints", "-10.5,3.25:20,-7.5:+5,40", V),
    ("point", "-10.5,3.25:20,-7.5:+5,40", V),
    ("convex_polygon", ".5,-.5", X),
    ("waypoints", ".5,-.5", V),
    ("point", ".5,-.5", V),
    ("convex_polygon", "0,0 : 100,0 : 50,80", V),
    ("waypoints", "0,0 : 100,0 : 50,80", V),
    ("point", "0,0 : 100,0 : 50,80", V),
    ("convex_polygon", "0,0,5:10,0,5:10,10,5", V),
    ("waypoints", "0,0,5:10,0,5:10,10,5", V),
    ("point", "0,0,5:10,0,5:10,10,5", V),
    ("convex_polygon", "0,0:-50,-50:0,-100:50,-50", V),
    ("waypoints", "0,0:-50,-50:0,-100:50,-50", V),
    ("point", "0,0:-50,-50:0,-100:50,-50", V),
    ("convex_polygon", "0,0:0,10:10,10:10,0", V),
    ("waypoints", "0,0:0,10:10,10:10,0", V),
    ("point", "0,0:0,10:10,10:10,0", V),
    ("waypoints", "0,0:0.1,0.3:0.2,0.6:1,0", V),
    ("point", "0,0:0.1,0.3:0.2,0.6:1,0", V),
    ("convex_polygon", "0,0:10,0:10,10,5", V),
    ("waypoints", "0,0:10,0:10,10,5", V),
    ("point", "0,0:10,0:10,10,5", V),
    ("convex_polygon", "0,0:10,0:10,10,abc", X),
    ("waypoints", "0,0:10,0:10,10,abc", X),
    ("point", "0,0:10,0:10,10,abc", V),
    ("convex_polygon", "0,0:10,0:10,10,z", X),
    ("waypoints", "0,0:10,0:10,10,z", X),
    ("point", "0,0:10,0:10,10,z", V),
    ("convex_polygon", "0,0:10,0:10,10:", V),
    ("waypoints", "0,0:10,0:10,10:", V),
    ("point", "0,0:10,0:10,10:", V),
    ("convex_polygon", "0,0:10,0:10,10:0,10:5,-1", X),
    ("waypoints", "0,0:10,0:10,10:0,10:5,-1", V),
    ("point", "0,0:10,0:10,10:0,10:5,-1", V),
    ("convex_polygon", "0,0:100,0:100,100:0,100", V),
    ("waypoints", "0,0:100,0:100,100:0,100", V),
    ("point", "0,0:100,0:100,100:0,100", V),
    ("convex_polygon", "0,0:100,0:100,100:0,100:50,50", X),
    ("waypoints", "0,0:100,0:100,100:0,100:50,50", V),
    ("point", "0,0:100,0:100,100:0,100:50,50", V),
    ("convex_polygon", "0,0:100,0:100,100:0,100:label,one:vertex_size,3:edge_color,red", V),
    ("waypoints", "0,0:100,0:100,100:0,100:label,one:vertex_size,3:edge_color,red", V),
    ("point", "0,0:100,0:100,100:0,100:label,one:vertex_size,3:edge_color,red", V),
    ("convex_polygon", "0,0:100,0:50,20:100,100:0,100", X),
    ("waypoints", "0,0:100,0:50,20:100,100:0,100", V),
    ("point", "0,0:100,0:50,20:100,100:0,100", V),
    ("convex_polygon", "0,0:1e3,0:0,5", X),
    ("waypoints", "0,0:1e3,0:0,5", X),
    ("point", "0,0:1e3,0:0,5", V),
    ("waypoints", "0,0:3,1:6,2:0,5", V),
    ("point", "0,0:3,1:6,2:0,5", V),
    ("convex_polygon", "0,0:50,0:100,0:50,50", V),
    ("waypoints", "0,0:50,0:100,0:50,50", V),
    ("point", "0,0:50,0:100,0:50,50", V),
    ("convex_polygon", "0,0::10,0:10,10", X),
    ("waypoints", "0,0::10,0:10,10", X),
    ("point", "0,0::10,0:10,10", V),
    ("convex_polygon", "0.1,0.2:0.7,0.1:0.9,0.8", V),
    ("waypoints", "0.1,0.2:0.7,0.1:0.9,0.8", V),
    ("point", "0.1,0.2:0.7,0.1:0.9,0.8", V),
    ("convex_polygon", "1 , 2", X),
    ("waypoints", "1 , 2", V),
    ("point", "1 , 2", V),
    ("convex_polygon", "1,-", X),
    ("waypoints", "1,-", X),
    ("point", "1,-", X),
    ("convex_polygon", "1,1:1,1:1,1", X),
    ("waypoints", "1,1:1,1:1,1", V),
    ("point", "1,1:1,1:1,1", V),
    ("convex_polygon", "1,2,3,4:5,6:7,8", X),
    ("waypoints", "1,2,3,4:5,6:7,8", X),
    ("point", "1,2,3,4:5,6:7,8", V),
    ("convex_polygon", "1.5.,2", X),
    ("waypoints", "1.5.,2", X),
    ("point", "1.5.,2", X),
    ("convex_polygon", "10,20", X),
    ("waypoints", "10,20", V),
    ("point", "10,20", V),
    ("convex_polygon", "10,20:label,a", X),
    ("waypoints", "10,20:label,a", V),
    ("point", "10,20:label,a", V),
    ("convex_polygon", "10:20", X),
    ("waypoints", "10:20", X),
    ("point", "10:20", V),
    ("convex_polygon", "3,4:foo", X),
    ("waypoints", "3,4:foo", X),
    ("point", "3,4:foo", V),
    ("convex_polygon", "3:4", X),
    ("waypoints", "3:4", X),
    ("point", "3:4", V),
    ("convex_polygon", "40;-60", X),
    ("waypoints", "40;-60", X),
    ("point", "40;-60", X),
    ("convex_polygon", "5.,6.", X),
    ("waypoints", "5.,6.", V),
    ("point", "5.,6.", V),
    ("convex_polygon", "60,-40 : 60,-160", X),
    ("waypoints", "60,-40 : 60,-160", V),
    ("point", "60,-40 : 60,-160", V),
    ("convex_polygon", "60,-40:60", X),
    ("waypoints", "60,-40:60", X),
    ("point", "60,-40:60", V),
    ("convex_polygon", "60,-40:60,-160:150,-160:180,-100:150,-40", V),
    ("waypoints", "60,-40:60,-160:150,-160:180,-100:150,-40", V),
    ("point", "60,-40:60,-160:150,-160:180,-100:150,-40", V),
    ("convex_polygon", ":", X),
    ("waypoints", ":", X),
    ("point", ":", X),
    ("convex_polygon", ":0,0:10,0:10,10", X),
    ("waypoints", ":0,0:10,0:10,10", X),
    ("point", ":0,0:10,0:10,10", V),
    ("convex_polygon", "::", X),
    ("waypoints", "::", X),
    ("point", "::", X),
    ("convex_polygon", "LABEL,x:0,0:1,0:0,1", V),
    ("waypoints", "LABEL,x:0,0:1,0:0,1", V),
    ("point", "LABEL,x:0,0:1,0:0,1", V),
    ("convex_polygon", "Label,A:0,0:5,0:0,5", V),
    ("waypoints", "Label,A:0,0:5,0:0,5", V),
    ("point", "Label,A:0,0:5,0:0,5", V),
    ("convex_polygon", "START", X),
    ("waypoints", "START", V),
    ("point", "START", X),
    ("convex_polygon", "a,b:3,4", X),
    ("waypoints", "a,b:3,4", X),
    ("point", "a,b:3,4", V),
    ("convex_polygon", "active=false", X),
    ("waypoints", "active=false", X),
    ("point", "active=false", X),
    ("convex_polygon", "active=false,label=foo", X),
    ("waypoints", "active=false,label=foo", X),
    ("point", "active=false,label=foo", X),
    ("convex_polygon", "empty", X),
    ("waypoints", "empty", V),
    ("point", "empty", X),
    ("point", "format=radial,x=0,y=0,radius=10,pts=8", V),
    ("convex_polygon", "hdg=3,x=1,y=2", X),
    ("waypoints", "hdg=3,x=1,y=2", X),
    ("point", "hdg=3,x=1,y=2", V),
    ("convex_polygon", "here", X),
    ("waypoints", "here", X),
    ("point", "here", X),
    ("convex_polygon", "label,a:active,false", X),
    ("waypoints", "label,a:active,false", X),
    ("point", "label,a:active,false", X),
    ("convex_polygon", "label,foo:0,0:100,0:100,100", V),
    ("waypoints", "label,foo:0,0:100,0:100,100", V),
    ("point", "label,foo:0,0:100,0:100,100", V),
    ("convex_polygon", "label,foo:active,false", X),
    ("waypoints", "label,foo:active,false", X),
    ("point", "label,foo:active,false", X),
    ("convex_polygon", "label=a,pts={0,0:10,0:10,10},active=false", V),
    ("waypoints", "label=a,pts={0,0:10,0:10,10},active=false", V),
    ("point", "label=a,pts={0,0:10,0:10,10},active=false", V),
    ("convex_polygon", "label=foo,pts={0,0:10,0:10,10}", V),
    ("waypoints", "label=foo,pts={0,0:10,0:10,10}", V),
    ("point", "label=foo,pts={0,0:10,0:10,10}", V),
    ("convex_polygon", "points:1,2:3,4", X),
    ("waypoints", "points:1,2:3,4", V),
    ("point", "points:1,2:3,4", V),
    ("convex_polygon", "points:1,2:3,4:5,6", X),
    ("waypoints", "points:1,2:3,4:5,6", V),
    ("point", "points:1,2:3,4:5,6", V),
    ("convex_polygon", "pts:1,2:3,4", X),
    ("waypoints", "pts:1,2:3,4", V),
    ("point", "pts:1,2:3,4", V),
    ("convex_polygon", "pts:{1,2:3,4}", X),
    ("waypoints", "pts:{1,2:3,4}", X),
    ("point", "pts:{1,2:3,4}", X),
    ("convex_polygon", "pts=0,0:10,0:10,10", X),
    ("waypoints", "pts=0,0:10,0:10,10", X),
    ("point", "pts=0,0:10,0:10,10", V),
    ("convex_polygon", "pts={0,0:10,0:10,10} label=a", X),
    ("waypoints", "pts={0,0:10,0:10,10} label=a", X),
    ("point", "pts={0,0:10,0:10,10} label=a", V),
    ("convex_polygon", "pts={0,0:10,0:10,10}label=x", X),
    ("waypoints", "pts={0,0:10,0:10,10}label=x", X),
    ("point", "pts={0,0:10,0:10,10}label=x", V),
    ("convex_polygon", "pts={0,0:100,0:100,100:0,100},label=foo", V),
    ("waypoints", "pts={0,0:100,0:100,100:0,100},label=foo", V),
    ("point", "pts={0,0:100,0:100,100:0,100},label=foo", V),
    ("convex_polygon", "pts={0,0:100,0:100,1OO}", X),
    ("waypoints", "pts={0,0:100,0:100,1OO}", X),
    ("point", "pts={0,0:100,0:100,1OO}", V),
    ("convex_polygon", "pts={1,2:3,4:5,6", X),
    ("waypoints", "pts={1,2:3,4:5,6", V),
    ("point", "pts={1,2:3,4:5,6", V),
    ("convex_polygon", "pts={1,2:3,4:5,6}x", X),
    ("waypoints", "pts={1,2:3,4:5,6}x", X),
    ("point", "pts={1,2:3,4:5,6}x", V),
    ("convex_polygon", "pts={60,-40:60,-160:150,-160}", V),
    ("waypoints", "pts={60,-40:60,-160:150,-160}", V),
    ("point", "pts={60,-40:60,-160:150,-160}", V),
    ("convex_polygon", "pts={x=1,y=2:x=3,y=4}", X),
    ("waypoints", "pts={x=1,y=2:x=3,y=4}", V),
    ("point", "pts={x=1,y=2:x=3,y=4}", X),
    ("convex_polygon", "pts={}", X),
    ("waypoints", "pts={}", X),
    ("point", "pts={}", X),
    ("point", "radial:0,0,10,8", X),
    ("convex_polygon", "start", X),
    ("waypoints", "start", V),
    ("point", "start", X),
    ("convex_polygon", "x=,y=2", X),
    ("waypoints", "x=,y=2", X),
    ("point", "x=,y=2", X),
    ("convex_polygon", "x=1", X),
    ("waypoints", "x=1", X),
    ("point", "x=1", X),
    ("convex_polygon", "x=1,y=2:label,a", X),
    ("waypoints", "x=1,y=2:label,a", X),
    ("point", "x=1,y=2:label,a", V),
    ("convex_polygon", "x=10", X),
    ("waypoints", "x=10", X),
    ("point", "x=10", X),
    ("convex_polygon", "x=10,y=20", X),
    ("waypoints", "x=10,y=20", X),
    ("point", "x=10,y=20", V),
    ("convex_polygon", "x=a,y=b", X),
    ("waypoints", "x=a,y=b", X),
    ("point", "x=a,y=b", V),
]

#: forms the port does not follow exactly, and values whose convexity rests on rounding
NOT_JUDGED = [
    ("convex_polygon", "0,0:0.1,0.3:0.2,0.6:1,0"),
    ("convex_polygon", "0,0:3,1:6,2:0,5"),
    ("convex_polygon", "format=radial,x=0,y=0,radius=10,pts=8"),
    ("convex_polygon", "radial:0,0,10,8"),
    ("waypoints", "format=radial,x=0,y=0,radius=10,pts=8"),
    ("waypoints", "radial:0,0,10,8"),
    ("convex_polygon", "$(POLY)"),
    ("point", "$(START_POS)"),
    ("waypoints", "format=zigzag, 0, 0, 45, 100, 20, 50"),
    ("convex_polygon", "ellipse: x=0, y=0, major=40, minor=20, degs=0, pts=8"),
    ("convex_polygon", "pylon: x1=0, y1=0, x2=20, y2=0, axis_pad=5"),
]


@pytest.mark.parametrize(("form", "value", "verdict"), AGREED)
def test_agrees_with_the_cpp_parser(form, value, verdict):
    assert judge(form, value).status == verdict


@pytest.mark.parametrize(("form", "value"), NOT_JUDGED)
def test_unported_forms_are_unknown(form, value):
    assert judge(form, value).status == UNKNOWN
    assert problem(form, value) is None


def test_reasons_name_the_fault():
    assert judge("convex_polygon", "60,-40 : 60").reason == "vertex 2 `60` has no y"
    assert judge("convex_polygon", "60,-40 : 60,-160").reason == (
        "only 2 vertices: a polygon needs 3"
    )
    assert judge("convex_polygon", "0,0:100,0:50,20:100,100:0,100").reason == (
        "the polygon is not convex"
    )
    assert "`1OO` is not a number" in judge("convex_polygon", "pts={0,0:100,0:100,1OO}").reason


def test_problem_reports_only_sure_rejections():
    assert problem("convex_polygon", "0,0:10,0:10,10") is None
    assert problem("convex_polygon", "0,0:10,0").startswith("is not a convex polygon")
    assert problem("waypoints", "1,2:3").startswith("is not a point list or polygon")
    assert problem("point|start|empty", "Start") is None
    assert problem("point", "here") == "is not a point (no `x,y` point)"


@pytest.mark.parametrize(
    "value", ["", ":", "{", "pts={", "\t", "1" * 5000 + ",2:3,4:5,6", "a" * 300]
)
def test_odd_input_never_raises(value):
    for form in ("convex_polygon", "waypoints", "point", "point|start"):
        assert judge(form, value).status in (VALID, INVALID, UNKNOWN)


@pytest.mark.parametrize(
    ("text", "pair"),
    [
        ("MODE=SURVEY", ("MODE", "SURVEY")),
        ("  MODE = SURVEY  ", ("MODE", "SURVEY")),
        ("MODE==SURVEY", ("MODE", "=SURVEY")),  # split at the first `=`
        ("<25 CLOSE = true", ("CLOSE", "true")),  # a post tag in front
        ("#shoreside DEPLOY=false", ("DEPLOY", "false")),  # a destination tag
        ("NEXT=$[INDEX] [if] MODE=RUN", ("NEXT", "$[INDEX]")),  # a condition behind
        ("MODE=", None),  # an empty side: rejected
        ("=SURVEY", None),
        ("", None),
    ],
)
def test_var_data_pair_splits_as_the_helm_does(text, pair):
    from moos_lint.semantics.mbutil import var_data_pair

    assert var_data_pair(text) == pair
