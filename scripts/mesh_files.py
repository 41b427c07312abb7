"""Reading the program's meshes and results (.vtu, through meshio, whichever encoding the
program writes) and the JSON files beside them (X.stats.json of `vorodg mesh`, X.metrics.json of
`vorodg solve`)."""
import json
import os

import numpy as np

from plotting_common import InputError

# The cell types a polygon mesh can hold, as meshio names them.
DRAWABLE = ("triangle", "polygon", "pixel", "quad")


class MeshFile:
    """A mesh or result file: points (n x 2), cells (vertex index arrays, in file order) and the
    file's point, cell and field data."""

    def __init__(self, path):
        import meshio  # only here: a slow import that the JSON-only paths do not need

        try:
            mesh = meshio.read(path, file_format="vtu")
        except Exception as e:  # meshio raises ReadError, ValueError, KeyError, ... on bad files
            raise InputError(f"{path}: cannot read the .vtu file: {e}") from None
        self.path = path
        points = np.asarray(mesh.points, dtype=float)
        if points.ndim != 2 or points.shape[1] < 2:
            raise InputError(f"{path}: points of shape {points.shape}, need n x 2 or more")
        self.points = points[:, :2]
        self.cells = []
        for block in mesh.cells:
            if block.type not in DRAWABLE:
                raise InputError(f"{path}: cells of unsupported type {block.type!r}")
            data = np.asarray(block.data, dtype=np.int64)
            if block.type == "pixel":  # pixels are numbered row by row
                data = data[:, [0, 1, 3, 2]]
            self.cells.extend(data)
        conn = np.concatenate(self.cells) if self.cells else np.zeros(0, dtype=np.int64)
        if conn.size and (conn.min() < 0 or conn.max() >= len(self.points)):
            raise InputError(f"{path}: connectivity refers to a point that does not exist")
        # meshio splits the cells into blocks of one type and size; the data follows the blocks.
        self._data = {"PointData": {k: np.asarray(v) for k, v in mesh.point_data.items()},
                      "CellData": {k: np.concatenate([np.asarray(b) for b in v])
                                   for k, v in mesh.cell_data.items()}}
        self._domain = mesh.field_data.get("domain")

    def names(self, section):
        return list(self._data[section])

    def array(self, section, name):
        """PointData or CellData array `name` as (n x components), n = points or cells."""
        arrays = self._data[section]
        if name not in arrays:
            other = "CellData" if section == "PointData" else "PointData"
            where = f" (it is {other})" if name in self._data[other] else ""
            have = ", ".join(arrays) or "none"
            raise InputError(f"{self.path}: no {section} array {name!r}{where}; "
                             f"{section} arrays: {have}")
        values = np.asarray(arrays[name], dtype=float)
        count = len(self.points) if section == "PointData" else len(self.cells)
        values = values.reshape(len(values), -1) if values.size else values.reshape(0, 1)
        if len(values) != count:
            raise InputError(f"{self.path}: {section} {name!r} has {len(values)} tuples "
                             f"for {count}")
        return values

    def domain(self):
        """The domain rectangle (x0, y0, x1, y1) from the field data, or None."""
        if self._domain is None:
            return None
        values = np.asarray(self._domain, dtype=float).ravel()
        return tuple(float(v) for v in values) if values.size == 4 else None

    def sides(self):
        return np.fromiter((len(c) for c in self.cells), dtype=np.int64, count=len(self.cells))


def mentions_array(path, name):
    """Whether the file names a DataArray `name` (the XML headers stay plain text in every
    encoding: a cheap test before reading)."""
    try:
        with open(path, "rb") as f:
            return f'Name="{name}"'.encode() in f.read()
    except OSError:
        return False


def read_stats(path):
    """The statistics or metrics JSON beside a mesh ({} when there is none)."""
    if path is None:
        return {}
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        raise InputError(f"{path}: cannot read statistics: {e}") from None


def histogram(value):
    """A side-count histogram from the stats JSON: {"k": count} (or [[k, count], ...])."""
    if not value:
        return {}
    items = value.items() if isinstance(value, dict) else value
    return {int(k): int(n) for k, n in items}


def stem_of(vtu_path):
    name = os.path.basename(vtu_path)
    return name[:-4] if name.endswith(".vtu") else name


def default_stats_path(vtu_path, suffixes=(".stats.json",)):
    base = vtu_path[:-4] if vtu_path.endswith(".vtu") else vtu_path
    for suffix in suffixes:
        candidate = base + suffix
        if os.path.exists(candidate):
            return candidate
    return None


def parse_mesh_argument(arg, suffixes=(".stats.json",)):
    """'mesh.vtu[:stats.json]' -> (vtu, stats or None). Only a trailing ':...json' is split off."""
    head, sep, tail = arg.rpartition(":")
    if sep and tail.endswith(".json") and head:
        return head, tail
    return arg, default_stats_path(arg, suffixes)
