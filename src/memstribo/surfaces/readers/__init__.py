"""Read measured surfaces: instrument files -> :class:`~memstribo.surfaces.roughness.Profile` or :class:`SurfaceMap`.

Every format SurfaceTopography reads goes through it first (imported lazily, it takes
seconds), with the file's channels, units and sizes: instrument files, and text or CSV files
with an instrument header such as a Bruker Dektak CSV export. memstribo reads these itself
(see data/afm/README.md, "Reader notes and pitfalls"):

- plain numeric x-z (or z) text/CSV (``#`` comments, whitespace, commas or semicolons, one
  optional line of column names whose units, ``x [um], z [nm]``, are honoured per axis) and
  ``.npy`` (n x 2 or 2 x n) profiles: own strict readers (SurfaceTopography would silently
  skip unreadable leading rows and ignore such a header); heights in metres unless ``unit``
  says otherwise; text in UTF-8 with or without BOM, UTF-16, Latin-1, any line ends;
- the one-line text export with an 11-line header ("Name : ... (128x128)", "Z Unit : nm"),
  e.g. ``topography_in_nanometers.txt``: own reader (SurfaceTopography returns a 16384 x 1 map);
- contact.engineering containers (``.zip`` with ``meta.yml``): every member is opened on its
  own; the member's own calibration is used, *not* meta.yml's ``height_scale`` on top of it
  (that would apply the NanoScope scale twice); meta.yml gives the unit of unit-less members;
- Park TIFF and every other SurfaceTopography map: SurfaceTopography's ``heights()`` is
  indexed [x, y]; memstribo stores (ny, nx) with rows = scan lines along x;
- Asylum ``.ibw``: pixel size ScanSize / points (SurfaceTopography uses ScanSize / (points - 1));
  a note whose ScanPoints/ScanLines contradict the wave, or whose size is not finite, is refused;
- NanoScope: an image section whose line counts do not fill its data block is refused
  (SurfaceTopography would take the global counts and rescale the scan size); Gwyddion: a negative
  size is refused (SurfaceTopography takes its absolute value).

A file that no reader takes gets one message: why it is not x-z text, what SurfaceTopography
said for its format (one clause, never its list of every reader), what is supported. Text
from the file is shown with control characters escaped. TIFF and Igor files cut short are
refused even where the cut spares the heights. Numbers are ASCII digits (Python's ``float()``
also reads full-width and Arabic-Indic ones); a text header naming the height column before x,
float16 ``.npy`` arrays and constant surfaces are refused.

The package has one module per family of formats: :mod:`.instruments` (SurfaceTopography),
:mod:`.text`, :mod:`.numpy_files`, :mod:`.containers`; :mod:`.topography` picks the reader and
:mod:`._common` holds the map type and the checks they share.
"""

from __future__ import annotations

from memstribo.surfaces.readers._common import LENGTH_UNITS, MAX_POINTS, SUPPORTED_EXTENSIONS, SurfaceMap
from memstribo.surfaces.readers.numpy_files import read_height_array
from memstribo.surfaces.readers.topography import read_topography, write_profile

__all__ = ["SurfaceMap", "read_topography", "write_profile", "read_height_array", "SUPPORTED_EXTENSIONS",
           "LENGTH_UNITS", "MAX_POINTS"]

for _name in ("SurfaceMap", "read_topography", "write_profile", "read_height_array"):
    globals()[_name].__module__ = __name__  # documented and pickled under the public path
del _name
