"""pMarineViewer's background images: where on the earth each one lies.

A ``tiff_file`` image comes with an ``.info`` file of the same name that gives the
latitudes of its north and south edges and the longitudes of its east and west edges
(MOOS-IvP's lib_marineview/BackImg.cpp:393-435 reads ``lat_north``, ``lat_south``,
``lon_west`` and ``lon_east``, each line cut at ``//``, a later line replacing an earlier
one; an image described only in the older ``img_centx`` form is placed on the local grid,
not on the earth). The viewer puts the image's own datum (``datum_lat``/``datum_lon``, or
its centre) at the local grid's (0, 0), so a mission whose origin lies far from its image
still shows its vehicles on it, on the wrong shore: an origin far from every image and on
one once its two values are swapped back is a swapped origin (latlong-origin).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: the mean radius of the Earth, metres (enough for a distance told in metres or km)
_EARTH = 6_371_000.0

#: the keys of an ``.info`` file that place its image on the earth
BOUNDS = ("lat_north", "lat_south", "lon_east", "lon_west")


@dataclass(frozen=True, slots=True)
class ImageBox:
    """An image's edges in decimal degrees, and the ``.info`` file that gives them."""

    lat_north: float
    lat_south: float
    lon_east: float
    lon_west: float
    source: str

    def nearest(self, lat: float, lon: float) -> tuple[float, float]:
        """The point of the image nearest to ``(lat, lon)`` (the point itself when on it)."""
        return (
            min(max(lat, self.lat_south), self.lat_north),
            min(max(lon, self.lon_west), self.lon_east),
        )

    def shown(self) -> str:
        return f"lat {self.lat_south} to {self.lat_north}, lon {self.lon_west} to {self.lon_east}"


def image_box(text: str, source: str) -> ImageBox | None:
    """The edges an ``.info`` file's ``text`` gives (None unless all four, as numbers, with
    north above south and east of west, as the viewer requires)."""
    found: dict[str, float] = {}
    for line in text.splitlines():
        left, eq, right = line.split("//", 1)[0].partition("=")
        key = left.strip()
        if not eq or key not in BOUNDS:
            continue
        try:
            found[key] = float(right.strip())
        except ValueError:
            continue
    if len(found) != len(BOUNDS):
        return None
    box = ImageBox(source=source, **found)
    if box.lat_north <= box.lat_south or box.lon_east <= box.lon_west:
        return None
    return box


def info_name(tiff: str) -> str:
    """The ``.info`` file of image ``tiff`` (``forrest19.tif`` -> ``forrest19.info``)."""
    base, dot, ext = tiff.rpartition(".")
    return f"{base}.info" if dot and ext.lower() in ("tif", "tiff") else f"{tiff}.info"


def apart(a: tuple[float, float], b: tuple[float, float]) -> float:
    """Metres between two points (lat, lon) in degrees, a few kilometres apart or more."""
    la1, lo1, la2, lo2 = (math.radians(v) for v in (*a, *b))
    h = (
        math.sin((la2 - la1) / 2) ** 2
        + math.cos(la1) * math.cos(la2) * math.sin((lo2 - lo1) / 2) ** 2
    )
    return 2 * _EARTH * math.asin(min(1.0, math.sqrt(h)))
