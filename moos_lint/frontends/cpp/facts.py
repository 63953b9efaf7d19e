"""What MOOS and MOOS-IvP's own functions and variables mean for units, sense and range.

One table per kind of fact, each entry with its evidence in the MOOS sources, so
that the value analysis (:mod:`moos_lint.frontends.cpp.values`) and every rule built on it
read the same facts.
"""

from __future__ import annotations

import math

#: Conversion helpers: name -> (unit in, unit out, output range in the output unit, sense).
#: ``None`` for "as the argument" / "unknown". Evidence:
#: - ``MOOSDeg2Rad`` returns ``dfDeg*PI/180.0``; ``MOOSRad2Deg`` ``dfRad*180.0/PI``
#:   (core-moos Core/libMOOS/Utils/MOOSUtilityFunctions.cpp).
#: - ``MOOS_ANGLE_WRAP`` shifts by π, ``fmod(·, 2*PI)`` and shifts back: ±π (same file).
#: - ``degToRadians`` returns ``(degval/180.0) * M_PI``; ``radToDegrees``
#:   ``(radval / M_PI) * 180``; ``radAngleWrap`` one shift by 2π into ±π;
#:   ``angle180`` into (-180, 180]; ``angle360`` into [0, 360);
#:   ``headingToRadians`` is ``radAngleWrap((90.0-degval)*M_PI/180.0)`` (the math
#:   frame: counter-clockwise from east); ``radToHeading`` is
#:   ``angle360(90.0-(radval / M_PI) * 180)``; ``relAng`` a compass bearing in
#:   [0, 360) (moos-ivp ivp/src/lib_geometry/AngleUtils.cpp).
#: - The bearings and differences of the same file are degrees: ``relBearing`` is
#:   ``angle360(relAng(os, cn) - osh)``, ``absRelBearing`` its ``angle180`` made
#:   positive ([0, 180]), ``totAbsRelBearing`` the sum of two of those ([0, 360]),
#:   ``angleDiff`` the smaller difference of two ``angle360`` ([0, 180]), ``aspectDiff``
#:   the smaller ``angleDiff`` with the second angle or its opposite ([0, 90]),
#:   ``headingAvg`` ``atan2(Σsin, Σcos) * 180 / M_PI`` made positive (a heading in
#:   [0, 360)), ``angleFromThreePoints`` an ``acos`` turned into degrees ([0, 180]).
#:   Apps define functions of their own named ``relBearing`` and ``angleDiff`` (in
#:   degrees, in other ranges: ``angleDiff`` into ±180), so those two give a unit and
#:   no range.
HELPERS: dict[str, tuple[str | None, str | None, tuple[float, float] | None, str | None]] = {
    "MOOSDeg2Rad": ("deg", "rad", None, None),
    "degToRadians": ("deg", "rad", None, None),
    "MOOSRad2Deg": ("rad", "deg", None, None),
    "radToDegrees": ("rad", "deg", None, None),
    "MOOS_ANGLE_WRAP": ("rad", "rad", (-math.pi, math.pi), None),
    "radAngleWrap": ("rad", "rad", (-math.pi, math.pi), None),
    "angle180": ("deg", "deg", (-180.0, 180.0), None),
    "angle360": ("deg", "deg", (0.0, 360.0), None),
    "headingToRadians": ("deg", "rad", (-math.pi, math.pi), "math"),
    "radToHeading": ("rad", "deg", (0.0, 360.0), "heading"),
    "relAng": (None, "deg", (0.0, 360.0), "heading"),
    "relBearing": (None, "deg", None, None),
    "absRelBearing": (None, "deg", (0.0, 180.0), None),
    "totAbsRelBearing": (None, "deg", (0.0, 360.0), None),
    "angleDiff": (None, "deg", None, None),
    "aspectDiff": (None, "deg", (0.0, 90.0), None),
    "headingAvg": (None, "deg", (0.0, 360.0), "heading"),
    "angleFromThreePoints": (None, "deg", (0.0, 180.0), None),
    # DUNE's Angles::degrees(rad) and Angles::radians(deg) (src/DUNE/Math/Angles.hpp:
    # ``return rad * 180.0 / c_pi``), as GLM's glm::degrees / glm::radians
    "degrees": ("rad", "deg", None, None),
    "radians": ("deg", "rad", None, None),
}

#: MOOS-IvP's MBUtils functions that give back their first argument rounded or clipped,
#: in its unit (lib_mbutil/MBUtils.cpp): ``snapToStep(orig_value, step)`` rounds to the
#: nearest multiple of ``step`` and ``snapDownToStep`` to the one below (lines 1972 and
#: 1999), ``vclip(var, low, high)``, ``vclip_min(var, low)`` and ``vclip_max(var, high)``
#: clip it (lines 1520, 1532 and 1542). Each maps to the places of its low and high bounds
#: among the arguments (the range of what it returns), None where it has none.
KEEPS_UNIT: dict[str, tuple[int | None, int | None]] = {
    "snapToStep": (None, None),
    "snapDownToStep": (None, None),
    "vclip": (1, 2),
    "vclip_min": (1, None),
    "vclip_max": (None, 1),
}

#: Inverse trigonometric functions of <cmath>: radians, in these ranges.
INVERSE_TRIG: dict[str, tuple[float, float]] = {
    "atan2": (-math.pi, math.pi),
    "atan": (-math.pi / 2, math.pi / 2),
    "asin": (-math.pi / 2, math.pi / 2),
    "acos": (0.0, math.pi),
}

#: Units of the MOOS-IvP variables an app reads by mail: name -> (unit, sense, range, sign).
#: uSimMarine publishes ``NAV_HEADING`` through ``angle360`` and ``NAV_YAW`` as
#: ``-degToRadians(angle180(heading))``, ``NAV_Z`` as ``-depth``
#: (moos-ivp ivp/src/dep_uSimMarine/SimEngine.cpp, uSimMarineV23/USM_MOOSApp.cpp); positions are
#: decimal degrees (lib_geodesy).
MAIL_UNITS: dict[str, tuple[str | None, str | None, tuple[float, float] | None, str | None]] = {
    "NAV_HEADING": ("deg", "heading", (0.0, 360.0), None),
    "DESIRED_HEADING": ("deg", "heading", (0.0, 360.0), None),
    "NAV_YAW": ("rad", "yaw", (-math.pi, math.pi), None),
    "NAV_PITCH": ("rad", None, (-math.pi, math.pi), None),
    "NAV_ROLL": ("rad", None, (-math.pi, math.pi), None),
    "NAV_DEPTH": (None, None, None, "down"),
    "DESIRED_DEPTH": (None, None, None, "down"),
    "NAV_Z": (None, None, None, "up"),
    "NAV_LAT": ("deg", None, None, None),
    "NAV_LONG": ("deg", None, None, None),
}

#: The helm's reads of its information buffer, which hold what :data:`MAIL_UNITS` says of
#: the MOOS variable named by their first argument: name -> the index of the argument set
#: to the value, None for the value returned. IvPBehavior's ``getBufferDoubleVal(varname,
#: ok)`` returns ``m_info_buffer->dQuery(varname, ok)`` (or the number its string value
#: holds), the variable's last value as the helm received it; ``getBufferDoubleValX(varname,
#: dval)`` sets ``dval`` to that (moos-ivp ivp/src/lib_behaviors/IvPBehavior.cpp).
BUFFER_READS: dict[str, int | None] = {"getBufferDoubleVal": None, "getBufferDoubleValX": 1}

#: NMEA 0183 sentences whose fields an app parses with atof/stod: their angles
#: (HDT/HDG/HDM headings, RMC/VTG courses, PASHR/PRDID attitude) are degrees by the
#: standard, as the proprietary ``$OHPR`` of OceanServer's compasses (heading, pitch and
#: roll in degrees: OceanServer Compass Manual, OS5000 Series, format type 0x02) and
#: Clearpath's front-seat ``$CPNVG`` (position as NMEA writes it, heading in degrees: the
#: Heron's iM300 of moos-ivp-pavlab, M300.cpp, handleMsgCPNVG). A literal naming one marks
#: a file as an NMEA parser.
NMEA_SENTENCES = (
    "HDT",
    "HDG",
    "HDM",
    "RMC",
    "VTG",
    "GGA",
    "GLL",
    "PASHR",
    "PRDID",
    "PTNTHPR",
    "XDR",
    "ROT",
    "THS",
    "OHPR",
    "CPNVG",
)

#: Devices whose text output an app parses with atof/strtod, every angle of it in degrees,
#: named in the app's code (its class, its app's name, a literal): a pattern of the name,
#: case aside -> (what a field read from it is, why its angles are degrees). OceanServer's
#: OS5000 compasses (and the OS4000 and OS3000 of the same family) send
#: ``$C<heading>P<pitch>R<roll>T<temperature>*cc``: "C" precedes the heading in degrees,
#: "P" the pitch angle in degrees, "R" the roll angle in degrees (OceanServer Compass
#: Manual, OS5000 Series, output format type 0x01, the "$C" format); their ``$OHPR``
#: sentence holds the same angles (it is in :data:`NMEA_SENTENCES`).
DEGREE_DEVICES: dict[str, tuple[str, str]] = {
    r"os[345]000": (
        "an OS5000 field",
        "the OceanServer OS5000 compass sends heading, pitch and roll in degrees",
    ),
}

#: NMEA 0183 sentences that give a position, its latitude and longitude written as
#: degrees and minutes run together, ``ddmm.mmmm`` and ``dddmm.mmmm`` (``4916.45`` is
#: 49°16.45′), each followed by its hemisphere: GGA's fields 2 and 4, RMC's 3 and 5, GLL's
#: 1 and 3 (NMEA 0183, v4.10), as Clearpath's ``$CPNVG`` its 2 and 4 (iM300 reads them
#: with ``latDDMMtoDD`` and ``lonDDDMMtoDDD``). A number parsed from such a sentence and
#: published as a latitude or longitude with no arithmetic on the way is not decimal degrees.
NMEA_POSITION_SENTENCES = ("GGA", "RMC", "GLL", "CPNVG")

#: Speeds in another unit than metres per second -> metres per second in one of them: the
#: knot is one nautical mile (1852 m) an hour, the mile an hour 1609.344 m an hour (both
#: exact by definition). MOOS speeds are metres per second (the MOOS conventions, SI units;
#: uSimMarine's NAV_SPEED, the helm's DESIRED_SPEED).
SPEED_UNITS: dict[str, float] = {"kn": 1852.0 / 3600.0, "km/h": 1.0 / 3.6, "mph": 0.44704}

#: NMEA 0183 sentences whose speed fields are knots or km/h, never metres per second:
#: sentence -> {field index, the sentence's name at 0: unit}; a field of the sentence not
#: listed is knots. RMC: 7 speed over ground, knots. VTG: 5 knots, 7 km/h. VHW: 5 speed
#: through water in knots, 7 in km/h. VBW: speeds in knots. (A sentence split without its
#: name shifts each index down by one: 4 and 6 are then VTG's knots and km/h.)
NMEA_SPEED_FIELDS: dict[str, dict[int, str]] = {
    "RMC": {},
    "VTG": {4: "kn", 5: "kn", 6: "km/h", 7: "km/h"},
    "VHW": {4: "kn", 5: "kn", 6: "km/h", 7: "km/h"},
    "VBW": {},
}

#: Library getters whose angle is known: name -> (unit, sense, range, what it is). MAVLink's
#: ATTITUDE message gives "the attitude in the aeronautical frame (right-handed, Z-down,
#: Y-right, X-front, ZYX, intrinsic)", yaw in rad, -pi..+pi (mavlink message_definitions
#: common.xml, ATTITUDE): about Z-down, its yaw turns clockwise from north, as a heading.
LIBRARY_ANGLES: dict[str, tuple[str, str, tuple[float, float], str]] = {
    "mavlink_msg_attitude_get_yaw": (
        "rad",
        "heading",
        (-math.pi, math.pi),
        "MAVLink's ATTITUDE yaw, about Z-down: clockwise from north",
    ),
    # VFR_HUD: "heading: Current heading in compass units (0-360, 0=north)", int16_t, deg
    "mavlink_msg_vfr_hud_get_heading": (
        "deg",
        "heading",
        (0.0, 360.0),
        "MAVLink's VFR_HUD heading, degrees clockwise from north",
    ),
}

#: Fields of library structs whose angle is known: (struct, field) -> as
#: :data:`LIBRARY_ANGLES`. MAVLink's generated C headers decode a message into a struct
#: (``mavlink_msg_attitude_decode(&msg, &att); att.yaw``) whose fields are the getters'
#: values (``mavlink_attitude_t``'s yaw in rad, -pi..+pi, about Z-down;
#: ``mavlink_vfr_hud_t``'s heading in degrees, 0..360).
#:
#: A key's class may carry its namespace (``IMC::EstimatedState``): it is then a field of
#: the class declared by its own name (``EstimatedState* msg``) only in a file that names
#: the namespace (``IMC::``), so a project's own class of that name is never taken for it.
#: LSTS's IMC (the messages DUNE and its MOOS bridges exchange) gives a vehicle's
#: ``EstimatedState`` as "lat: WGS-84 Latitude, rad", "lon: WGS-84 Longitude, rad" and
#: "psi: Rotation over z axis, rad" about z-down (NED): clockwise from north, as a heading
#: (imc IMC.xml, message EstimatedState).
LIBRARY_FIELDS: dict[tuple[str, str], tuple[str | None, str | None, tuple[float, float], str]] = {
    ("mavlink_attitude_t", "yaw"): LIBRARY_ANGLES["mavlink_msg_attitude_get_yaw"],
    ("mavlink_vfr_hud_t", "heading"): LIBRARY_ANGLES["mavlink_msg_vfr_hud_get_heading"],
    ("IMC::EstimatedState", "lat"): (
        "rad",
        None,
        (-math.pi / 2, math.pi / 2),
        "IMC's EstimatedState latitude, in radians",
    ),
    ("IMC::EstimatedState", "lon"): (
        "rad",
        None,
        (-math.pi, math.pi),
        "IMC's EstimatedState longitude, in radians",
    ),
    ("IMC::EstimatedState", "psi"): (
        "rad",
        "heading",
        (-math.pi, math.pi),
        "IMC's EstimatedState psi, radians about z-down: clockwise from north",
    ),
}

#: Methods of library classes whose angle is known: (class, method) -> as
#: :data:`LIBRARY_ANGLES`, for a method called on an object declared of that class
#: (``XsEuler euler = packet.orientationEuler(); euler.pitch()``), also where the
#: repository holds the library's code or defines a method of that name on a class of its
#: own (the value analysis finds a function's definitions by name). The Xsens
#: MT SDK's ``XsEuler`` holds Euler angles in degrees: xstypes/xseuler.c fills roll, pitch
#: and yaw with ``XsMath_rad2deg(...)`` of a quaternion (roll and yaw from atan2, pitch
#: from an asin), and xseuler.h's ``roll()``, ``pitch()``, ``yaw()`` (also ``x()``,
#: ``y()``, ``z()``) return them; the yaw's sense follows the frame the device is set to.
_XS_EULER = "the Xsens SDK's XsEuler holds Euler angles in degrees"
#: MOOS-IvP's ownship models hold the helm's NAV_HEADING as a behavior sets their pose:
#: lib_geometry's ``PlatModel::setOSH`` keeps ``angle360(osh)`` and ``getOSH()`` returns it
#: (PlatModel.cpp:67-70, PlatModel.h:70); lib_bhvutil's ``ObShipModelV24::getOSH()``
#: returns its PlatModel's (ObShipModelV24.h:76), lib_dep_behaviors' ``ObShipModel`` its
#: own ``angle360(osh)`` (ObShipModel.cpp:93, ObShipModel.h:61)
_OWNSHIP_HEADING = "MOOS-IvP's ownship heading, degrees clockwise from north"
#: MOOS-IvP's NodeRecord (lib_contacts) holds a node report's ``HDG=`` field as given
#: (``string2NodeRecord``: ``setHeading(atof(value))``, NodeRecordUtils.cpp), which
#: pNodeReporter fills with the vehicle's NAV_HEADING: ``getHeading()`` (NodeRecord.h:80)
#: is a heading in degrees
_NODE_HEADING = "a node report's HDG, the vehicle's heading in degrees clockwise from north"
LIBRARY_METHODS: dict[tuple[str, str], tuple[str, str | None, tuple[float, float], str]] = {
    **{
        ("XsEuler", method): ("deg", None, (-180.0, 180.0), _XS_EULER)
        for method in ("roll", "yaw", "x", "z")
    },
    **{("XsEuler", method): ("deg", None, (-90.0, 90.0), _XS_EULER) for method in ("pitch", "y")},
    **{
        (cls, "getOSH"): ("deg", "heading", (0.0, 360.0), _OWNSHIP_HEADING)
        for cls in ("PlatModel", "ObShipModel", "ObShipModelV24")
    },
    ("NodeRecord", "getHeading"): ("deg", "heading", (0.0, 360.0), _NODE_HEADING),
}

#: Methods of library classes that return an object of a library class: (class, method)
#: -> the class returned, so that a method called on what they return is read as that
#: class's (``packet.orientationEuler().yaw()``, with :data:`LIBRARY_METHODS`). The Xsens
#: MT SDK's xstypes/xsdatapacket.h: ``inline XsEuler orientationEuler() const`` (and its
#: overload taking a coordinate system) returns the packet's orientation as an
#: ``XsEuler``.
LIBRARY_RETURNS: dict[tuple[str, str], str] = {
    ("XsDataPacket", "orientationEuler"): "XsEuler",
}

#: Device libraries that hand a callback of the app's the readings they receive: the
#: class constructed -> (which of its arguments is the data callback, the elements of the
#: callback's array argument whose unit is known, that unit, why). Peter Bartz's Razor
#: AHRS interface (razor-9dof-ahrs C++/RazorAHRS.h: ``RazorAHRS(port, DataCallbackFunc data_func,
#: ErrorCallbackFunc error_func, Mode mode)``, RazorAHRS.cpp hands ``data_func`` the
#: floats the board sends, unchanged) reads a board whose firmware sends yaw, pitch and
#: roll first, in degrees, in every mode that outputs angles (Arduino/Razor_AHRS/
#: Output.ino, ``output_angles``: ``ypr[0] = TO_DEG(yaw); ypr[1] = TO_DEG(pitch);
#: ypr[2] = TO_DEG(roll)``). In its raw sensor modes the same elements are accelerations,
#: so the degrees are a hint (as a name's), never trusted where a name says otherwise.
LIBRARY_CALLBACKS: dict[str, tuple[int, frozenset[int], str, str]] = {
    "RazorAHRS": (
        1,
        frozenset({0, 1, 2}),
        "deg",
        "the Razor AHRS board sends yaw, pitch and roll in degrees",
    ),
}

#: CMOOSGeodesy's conversions between latitude/longitude and the local grid: name -> what
#: each argument is, in order. The two directions do not mirror each other: from lat/long
#: the north output comes first, into lat/long the east input does. Evidence: core MOOS's
#: MOOSGeodesy.h (libMOOSGeodesy, as MOOS-IvP ships it in MOOS_Jul2724):
#: ``LatLong2LocalUTM(double lat, double lon, double &MetersNorth, double &MetersEast)``,
#: ``LatLong2LocalGrid`` with the same parameters, ``LocalGrid2LatLong(double dfEast,
#: double dfNorth, double &dfLat, double &dfLon)`` and ``UTM2LatLong(double dfX, double dfY,
#: double &dfLat, double &dfLong)``, whose x is east (MOOSGeodesyProj.cpp:
#: ``double x = dfX + GetOriginEasting()``).
GEODESY_ARGUMENTS: dict[str, tuple[str, str, str, str]] = {
    "LatLong2LocalUTM": ("lat", "lon", "north", "east"),
    "LatLong2LocalGrid": ("lat", "lon", "north", "east"),
    "LocalGrid2LatLong": ("east", "north", "lat", "lon"),
    "UTM2LatLong": ("east", "north", "lat", "lon"),
}

#: Calls that turn text into a number.
TEXT_TO_NUMBER = {"atof", "stod", "strtod", "stof", "strtof", "stold", "strtold"}

#: Degrees to radians and back as plain numbers.
DEG2RAD = math.pi / 180.0
RAD2DEG = 180.0 / math.pi

#: Names of π and 2π in C/C++ code (<cmath>, MOOS's ``PI`` and ``TWO_PI``).
PI_NAMES = {"M_PI": math.pi, "PI": math.pi, "pi": math.pi, "TWO_PI": 2 * math.pi}

#: Any other conversion function named for what it does (``deg2rad``, ``XsMath_rad2deg``,
#: ``radToDeg``): the name is the evidence.
DEG2RAD_NAME = r"(?i)^(?:\w*_)?deg(?:rees?)?_?(?:2|to)_?rad(?:ians?)?$"
RAD2DEG_NAME = r"(?i)^(?:\w*_)?rad(?:ians?)?_?(?:2|to)_?deg(?:rees?)?$"

#: A constant named zero (``XsMath_zero``, ``ZERO``): 0, whatever its unit. Evidence: the
#: Xsens SDK's ``XSMATHCONST XsReal XsMath_zero = 0.0`` (xstypes/xsmath.h), which its
#: ``XsEuler_destruct`` writes to every angle.
ZERO_NAME = r"(?i)(?:^|_)zero$"

#: Calls that upper-case a string (an app that upper-cases a configured variable name
#: publishes it in upper case, whatever the mission writes): MOOS's ``MOOSToUpper``
#: (core-moos MOOSUtilityFunctions.h) and MOOS-IvP's ``toupper(string)`` (lib_mbutil
#: MBUtils.h) return an upper-cased copy; Boost's ``to_upper`` and ``std::transform``
#: with ``::toupper`` change their argument in place; ``to_upper_copy`` returns a copy.
UPPER_CASE_CALLS = frozenset(
    {"MOOSToUpper", "toupper", "to_upper", "to_upper_copy", "toUpper", "ToUpper", "upper"}
)

#: functions of C's math library that take their arguments by value and that the
#: analysis reads no unit from (not ``modf``, ``frexp`` or ``sincos``, which set a
#: variable through a pointer)
MATH_BY_VALUE = frozenset(
    f + suffix
    for f in (
        "fmod",
        "remainder",
        "sin",
        "cos",
        "tan",
        "sqrt",
        "cbrt",
        "pow",
        "hypot",
        "exp",
        "log",
        "log10",
        "fmin",
        "fmax",
        "copysign",
    )
    for suffix in ("", "f", "l")
)
