#!/usr/bin/env python3
"""Synthetic box sections for the damage map of `camouflet report`
(run_metrics.structure_damage / front_wall_halves, damage_map.py), printed as
'<name> <expected> <computed>' lines that tests/app/test_damage_map.cpp checks.

The box: front face r1 = 2 m, 1 m long, 0.5 m high from the ground down, walls
0.1 m, cells 0.05 m. The front wall's damage is its element centre's depth
below the roof over the height, D = (z_top - z) / H, so the lower half's mean
is 0.75 and the upper half's 0.25 exactly; the roof, floor and back wall carry
0.9, which a split that took in any other member would show. Every node is
displaced 30 mm up: centres by current position would move the row just below
mid-height into the upper half. In 3-D the box is two cell layers deep from
the symmetry plane y = 0; the layer off the plane carries damage 1, which the
section must leave out.

Usage: damage_map_cases.py WORKDIR (writes the synthetic output folders and
the figure of each there)."""
import os
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))
import damage_map  # noqa: E402
import run_metrics  # noqa: E402

R1, LENGTH, HEIGHT, WALL, CELL = 2.0, 1.0, 0.5, 0.1, 0.05
LIFT = 0.03  # m, every node's displacement, up


def damage_at(r, z):
    if r < R1 + WALL:
        return -z / HEIGHT
    return 0.9


def grid_rz():
    """Nodes (x, z) and quads of the box's section, the hollow left out; cell centres."""
    nr, nz = round(LENGTH / CELL), round(HEIGHT / CELL)
    nodes = [(R1 + i * CELL, -HEIGHT + j * CELL) for j in range(nz + 1) for i in range(nr + 1)]
    cells, centres = [], []
    for j in range(nz):
        for i in range(nr):
            r, z = R1 + (i + 0.5) * CELL, -HEIGHT + (j + 0.5) * CELL
            if R1 + WALL < r < R1 + LENGTH - WALL and -HEIGHT + WALL < z < -WALL:
                continue
            n0 = j * (nr + 1) + i
            cells.append((n0, n0 + 1, n0 + nr + 2, n0 + nr + 1))
            centres.append((r, z))
    return nodes, cells, centres


def write_vtu(path, points, displacement, cells, damage, cell_type):
    def arr(name, values, k, kind="Float64"):
        text = " ".join(" ".join(repr(float(v)) if kind == "Float64" else str(int(v)) for v in row)
                        if isinstance(row, (tuple, list)) else
                        (repr(float(row)) if kind == "Float64" else str(int(row))) for row in values)
        return f'<DataArray type="{kind}" Name="{name}" NumberOfComponents="{k}" format="ascii">{text}</DataArray>\n'

    n = len(cells[0])
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0">\n<UnstructuredGrid>\n'
                f'<Piece NumberOfPoints="{len(points)}" NumberOfCells="{len(cells)}">\n<PointData>\n')
        f.write(arr("displacement", displacement, 3))
        f.write("</PointData>\n<CellData>\n")
        f.write(arr("damage", damage, 1))
        f.write(arr("material", [2] * len(cells), 1, "Int32"))
        f.write("</CellData>\n<Points>\n" + arr("position", points, 3) + "</Points>\n<Cells>\n")
        f.write(arr("connectivity", cells, 1, "Int64"))
        f.write(arr("offsets", [(c + 1) * n for c in range(len(cells))], 1, "Int64"))
        f.write(arr("types", [cell_type] * len(cells), 1, "UInt8"))
        f.write("</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n")


def write_output(folder, three_d):
    os.makedirs(folder, exist_ok=True)
    nodes, quads, centres = grid_rz()
    if not three_d:
        points = [(r, z + LIFT, 0.0) for r, z in nodes]
        cells, damage = quads, [damage_at(r, z) for r, z in centres]
        cell_type = 9
    else:  # (r, z) as (x, z); layers at y = 0, CELL, 2 CELL
        m = len(nodes)
        points = [(r, k * CELL, z + LIFT) for k in range(3) for r, z in nodes]
        cells, damage = [], []
        for k in range(2):
            for q, (r, z) in zip(quads, centres):
                # VTK hexahedron: a face (here the one at y = k CELL) then the opposite one.
                cells.append(tuple(n + k * m for n in q) + tuple(n + (k + 1) * m for n in q))
                damage.append(damage_at(r, z) if k == 0 else 1.0)
        cell_type = 12
    displacement = [(0.0, 0.0, LIFT) if three_d else (0.0, LIFT, 0.0)] * len(points)
    write_vtu(os.path.join(folder, "fields_0001.vtu"), points, displacement, cells, damage, cell_type)
    with open(os.path.join(folder, "fields.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n'
                '<DataSet timestep="0.07" part="0" file="fields_0001.vtu"/>\n</Collection>\n</VTKFile>\n')
    gen = {"standoff_m": R1, "box_length_m": LENGTH, "box_height_m": HEIGHT, "wall_thickness_m": WALL,
           "top_depth_m": 0.0}
    return gen


def main(workdir):
    for name, three_d in (("rz", False), ("3d", True)):
        folder = os.path.join(workdir, name)
        gen = write_output(folder, three_d)
        dmg = run_metrics.structure_damage(folder, gen)
        lower, upper = dmg["front_wall_halves"]
        print(f"{name}_front_wall_lower_mean", 0.75, lower)
        print(f"{name}_front_wall_upper_mean", 0.25, upper)
        print(f"{name}_front_wall_mean", 0.5, dmg["mean"]["front wall"])
        print(f"{name}_section_elements", len(grid_rz()[1]), len(dmg["section"]["damage"]))
        print(f"{name}_section_time_s", 0.07, dmg["section"]["time"])
        fig, caption = damage_map.damage_map(dmg["section"], dmg["front_wall_halves"])
        fig.savefig(os.path.join(folder, "fig14_damage.png"), dpi=80)
        print(f"{name}_caption_names_time", 1, int("t = 70.0 ms" in caption))


if __name__ == "__main__":
    main(sys.argv[1])
