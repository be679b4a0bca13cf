"""From a real point file to a GeoJSON file and a picture, step by step (notebook-style:
each `# %%` block is a cell; run it in Jupyter/VS Code or as a script).

    python python/examples/point_file_to_geojson.py [POINT_FILE] [OUTPUT_DIR]

By default it reads tests/data/stretchdenoise/data/drillcase_xyz.txt (611 samples of a
drill case outline with three holes; GPL-3.0 data, see tests/data/README.md) and writes
drillcase_xyz.geojson and drillcase_xyz.png into OUTPUT_DIR (default: the current folder).
Needs matplotlib for the picture (`pip install matplotlib`); shapely is used if installed.
"""

# %% The input: any point file the command line reads (text, CSV, .node/.gtn)
import json
import sys
from pathlib import Path

import wdm_crust

ROOT = Path(__file__).resolve().parents[2]
path = Path(sys.argv[1]) if len(sys.argv) > 1 else (
    ROOT / "tests" / "data" / "stretchdenoise" / "data" / "drillcase_xyz.txt"
)
out = Path(sys.argv[2]) if len(sys.argv) > 2 else Path(".")
points = wdm_crust.read_points(path)  # (n, 2) float64; "file:line: ..." ValueError if bad
print(f"{path.name}: {len(points)} points")

# %% Reconstruct the curves and the medial axis
rec = wdm_crust.reconstruct(points)  # every --option of the command line, by keyword
print(rec)
for code, message in rec.warnings:  # what the command line prints as "warning: ..."
    print(f"warning: {code}: {message}")

# %% Polygons with holes: closed curves nested exactly, exterior CCW, holes CW
for k, polygon in enumerate(rec.polygons()):
    print(f"polygon {k}: exterior of {len(polygon.exterior)} points, "
          f"holes of {[len(h) for h in polygon.holes]} points")
try:
    from shapely.geometry import shape
except ImportError:
    pass
else:
    for polygon in rec.polygons():
        geometry = shape(polygon)  # via __geo_interface__
        print(f"  shapely: valid={geometry.is_valid}, area={geometry.area:.4g}")

# %% GeoJSON: the same bytes as `wdm-crust reconstruct FILE --format geojson`
geojson_path = out / f"{path.stem}.geojson"
geojson_path.write_text(rec.to_geojson())
kinds = [f["properties"]["kind"] for f in json.loads(geojson_path.read_text())["features"]]
print(f"wrote {geojson_path}: features {kinds}")

# %% The picture: points, closed curves, open chains, points on no curve, medial axis
import matplotlib

matplotlib.use("Agg")  # a file, no display needed
import matplotlib.pyplot as plt

fig, ax = plt.subplots(figsize=(8, 5.5))
wdm_crust.plot(rec, ax)
ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize="small")  # beside the shape
ax.set_title(f"{path.name}: {len(rec.polygons())} polygon(s), "
             f"{sum(len(p.holes) for p in rec.polygons())} hole(s)")
png_path = out / f"{path.stem}.png"
fig.savefig(png_path, dpi=110, bbox_inches="tight")
print(f"wrote {png_path}")
