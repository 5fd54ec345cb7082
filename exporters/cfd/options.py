"""Options of the CFD case (:class:`CfdOptions`) and the command-line flags that make them."""
from __future__ import annotations

import math
from dataclasses import dataclass

from lod2energy.errors import ParameterError

#: Default cell size (m) at the building surfaces.
DEFAULT_CELL_SIZE = 2.0


@dataclass(frozen=True)
class CfdOptions:
    """Options of :func:`export_case`.

    Parameters
    ----------
    region : (xmin, ymin, xmax, ymax) or None
        Rectangle in the input CRS (m).
    centre : (x, y) or None
        Circle centre in the input CRS; with ``radius``.
    radius : float or None, m
    wind_direction : float, deg
        Meteorological: the direction the wind comes from, clockwise from north.
    cell_size : float, m
        Cell size at the building surfaces.
    min_gap : float or None, m
        Gaps narrower than this are closed; None = ``cell_size``; 0 = none.
    mesh : bool
        Also run blockMesh, surfaceFeatureExtract, snappyHexMesh and checkMesh.
    iterations : int
        simpleFoam iterations written in controlDict.
    processors : int
        decomposeParDict subdomains.
    nice : int
        ``nice`` level of the meshing tools (0 = none).
    lod : str or None
        LoD used (default: highest).
    """

    region: tuple[float, float, float, float] | None = None
    centre: tuple[float, float] | None = None
    radius: float | None = None
    wind_direction: float = 270.0
    cell_size: float = DEFAULT_CELL_SIZE
    min_gap: float | None = None
    mesh: bool = False
    iterations: int = 1000
    processors: int = 2
    nice: int = 10
    lod: str | None = None

    def __post_init__(self):
        if not (isinstance(self.cell_size, (int, float)) and math.isfinite(self.cell_size) and self.cell_size > 0):
            raise ParameterError(f"--cell-size must be a positive number of metres, not {self.cell_size!r}")
        if self.min_gap is not None and not (math.isfinite(self.min_gap) and self.min_gap >= 0):
            raise ParameterError(f"--min-gap must be a non-negative number of metres, not {self.min_gap!r}")
        if not math.isfinite(self.wind_direction):
            raise ParameterError(f"--wind-direction must be finite, not {self.wind_direction!r}")
        from lod2energy.exporters.cfd.region import make_region
        make_region(self.region, self.centre, self.radius)  # raises on a bad region

    @property
    def gap(self) -> float:
        return self.cell_size if self.min_gap is None else float(self.min_gap)


def _floats(text: str, n: int, flag: str) -> tuple[float, ...]:
    try:
        vals = tuple(float(x) for x in str(text).split(","))
    except ValueError:
        raise ParameterError(f"{flag} needs {n} comma-separated numbers, not {text!r}") from None
    if len(vals) != n or not all(math.isfinite(v) for v in vals):
        raise ParameterError(f"{flag} needs {n} comma-separated finite numbers, not {text!r}")
    return vals


def add_cli_arguments(group) -> None:
    """Add ``--cfd --region --centre --radius --wind-direction --cell-size --min-gap --mesh``
    to an argparse parser or argument group."""
    group.add_argument("--cfd", action="store_true",
                       help="write an OpenFOAM v1912 case OUTDIR/cfd/ (domain by COST 732 / AIJ guidelines)")
    group.add_argument("--region", metavar="XMIN,YMIN,XMAX,YMAX", default=None,
                       help="export only the buildings meeting this rectangle in the input CRS, for every output "
                       "and the CFD case (buildings cut by its edge are kept whole; the others still serve as "
                       "neighbours)")
    group.add_argument("--centre", metavar="X,Y", default=None, help="region circle centre (input CRS)")
    group.add_argument("--radius", metavar="R", type=float, default=None, help="region circle radius (m)")
    group.add_argument("--wind-direction", metavar="DEG", type=float, default=270.0,
                       help="wind direction in degrees, meteorological: where the wind comes FROM, clockwise "
                            "from north (default 270, westerly)")
    group.add_argument("--cell-size", metavar="M", type=float, default=DEFAULT_CELL_SIZE,
                       help=f"cell size at the buildings in m (default {DEFAULT_CELL_SIZE:g})")
    group.add_argument("--min-gap", metavar="M", type=float, default=None,
                       help="close gaps between buildings narrower than M metres (default: the cell size; 0: none)")
    group.add_argument("--mesh", action="store_true",
                       help="also run blockMesh, surfaceFeatureExtract, snappyHexMesh and checkMesh")


def region_from_args(args):
    """The :class:`~lod2energy.exporters.cfd.region.Region` of ``--region`` or ``--centre`` /
    ``--radius``; None when neither is given (ParameterError on bad values)."""
    from lod2energy.exporters.cfd.region import make_region
    region, centre, radius = (getattr(args, k, None) for k in ("region", "centre", "radius"))
    if region is None and centre is None and radius is None:
        return None
    return make_region(_floats(region, 4, "--region") if region is not None else None,
                       _floats(centre, 2, "--centre") if centre is not None else None, radius)


def options_from_args(args) -> CfdOptions:
    """:class:`CfdOptions` from parsed arguments (ParameterError on bad values)."""
    region = getattr(args, "region", None)
    centre = getattr(args, "centre", None)
    return CfdOptions(
        region=_floats(region, 4, "--region") if region is not None else None,
        centre=_floats(centre, 2, "--centre") if centre is not None else None,
        radius=getattr(args, "radius", None),
        wind_direction=float(getattr(args, "wind_direction", 270.0)),
        cell_size=float(getattr(args, "cell_size", DEFAULT_CELL_SIZE)),
        min_gap=getattr(args, "min_gap", None),
        mesh=bool(getattr(args, "mesh", False)),
        lod=getattr(args, "lod", None),
    )
