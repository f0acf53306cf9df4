#!/usr/bin/env python3
"""Reads a run's last snapshot with VTK's own readers (Debian's python3-vtk9): the serial run's .vtu
and a run across MPI ranks' .pvtu (its pieces joined by vtkXMLPUnstructuredGridReader), and compares
every point and cell array, matched by the pieces' node_id and element_id (docs/parallel.md).

Usage: read_pvtu.py SERIAL_DIR RANKS_DIR TOLERANCE

Each array over its largest serial value (the files hold ten significant digits). Every node and
element of the serial mesh must be in the pieces (a node on a cut is in each piece that holds it,
with the same values). Exits 1 on a difference beyond TOLERANCE or a missing node or element.
"""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPUnstructuredGridReader, vtkXMLUnstructuredGridReader


def last_file(run_dir):
    """The last mesh file of the run's .pvd."""
    sets = ET.parse(run_dir / "fields.pvd").getroot().iter("DataSet")
    return run_dir / [d.get("file") for d in sets if d.get("part") == "0"][-1]


def load(path):
    reader = vtkXMLPUnstructuredGridReader() if path.suffix == ".pvtu" else vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    points = {"position": vtk_to_numpy(grid.GetPoints().GetData())}
    pd, cd = grid.GetPointData(), grid.GetCellData()
    for k in range(pd.GetNumberOfArrays()):
        points[pd.GetArrayName(k)] = vtk_to_numpy(pd.GetArray(k))
    cells = {}
    for k in range(cd.GetNumberOfArrays()):
        cells[cd.GetArrayName(k)] = vtk_to_numpy(cd.GetArray(k))
    return grid.GetNumberOfPoints(), grid.GetNumberOfCells(), points, cells


def compare(name, serial, ranks, ids, count, tolerance):
    """Largest difference of each array over its largest serial value; nodes seen on several
    pieces must agree with each other too."""
    worst = {}
    found = np.zeros(count, dtype=bool)
    index = ids.astype(np.int64) - 1
    found[index] = True
    for key, values in serial.items():
        if key not in ranks:
            print(f"{name} array '{key}' missing from the pieces")
            return None
        scale = np.max(np.abs(values)) or 1.0
        diff = np.max(np.abs(ranks[key] - values[index])) / scale
        worst[key] = diff
    if not found.all():
        print(f"{name}s missing from the pieces: {np.count_nonzero(~found)} of {count}")
        return None
    return worst


def main():
    serial_dir, ranks_dir, tolerance = Path(sys.argv[1]), Path(sys.argv[2]), float(sys.argv[3])
    serial_file, ranks_file = last_file(serial_dir), last_file(ranks_dir)
    if ranks_file.suffix != ".pvtu":
        print(f"{ranks_file.name}: not a .pvtu")
        return 1
    n, m, sp, sc = load(serial_file)
    n_r, m_r, rp, rc = load(ranks_file)
    pieces = len(list(ET.parse(ranks_file).getroot().iter("Piece")))
    print(f"{serial_file.name}: {n} points, {m} cells; {ranks_file.name}: {pieces} pieces, {n_r} points "
          f"(nodes on cuts in each piece that holds them), {m_r} cells")
    if m_r != m:
        print("the pieces do not hold every element once")
        return 1
    points = compare("node", sp, rp, rp["node_id"], n, tolerance)
    cells = compare("element", sc, rc, rc["element_id"], m, tolerance)
    if points is None or cells is None:
        return 1
    worst = {**{"point " + k: v for k, v in points.items()}, **{"cell " + k: v for k, v in cells.items()}}
    print(", ".join(f"{k} {v:.2g}" for k, v in worst.items()))
    bad = {k: v for k, v in worst.items() if not v <= tolerance}
    print("within" if not bad else f"beyond: {sorted(bad)}", f"{tolerance:g}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
