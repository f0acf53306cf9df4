"""The headline results of a buried-structure run, from its output folder.

One definition of each quantity, shared by `camouflet report`
(scripts/report.py) and `camouflet sweep` (scripts/sweep.py):
in-structure peak velocity and acceleration (Figs. 15-16), wall and floor
deflections (Fig. 12) and final displacements, structural damage (Fig. 14),
the apparent crater and the energy balance; and the TM 5-855-1 in-structure
averages from `camouflet empirical --csv`. Standard library and NumPy; the
low-passed peaks take SciPy's filters through structure_shock.py (imported
only where they are asked for).
docs/buried-structure.md ("The report", "Parameter studies") states the
definitions.
"""
import csv
import json
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np

G = 9.80665  # m/s^2 per g
F_COUPLING = 0.6  # the paper's coupling factor (section 5.3)

# (title, targets, axis, word): the front wall moves horizontally (targets 1-3),
# the floor vertically (targets 3-5), as the paper's Figs. 15 and 16.
# Upward speed above which soil that has left its place is in flight (crater(), m/s): ejecta leave at
# tens of m/s, the ground around a crater settles at well below this.
EJECTA_SPEED = 10.0

STRUCTURE_SETS = (("front wall", ("t1", "t2", "t3"), "x", "horizontal"),
                  ("floor", ("t3", "t4", "t5"), "y", "vertical"))
# (title, members.csv name, axis, word): the member averages the TM 5-855-1 comparison reads.
MEMBER_SETS = (("front wall", "front_wall", "x", "horizontal"), ("floor", "floor", "y", "vertical"))


def read_csv(path):
    """Gauge CSV -> (time array, {column: array})."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array([[float(x) for x in r] for r in rows[1:] if r], dtype=float)
    if data.size == 0:
        data = np.zeros((0, len(header)))
    cols = {name: data[:, k] for k, name in enumerate(header)}
    if any(name.endswith(".position_z") for name in header):
        cols = {symmetry_plane_name(name): v for name, v in cols.items()}
    return cols["time_s"], cols


def symmetry_plane_name(name):
    """3-D half model (docs/buried-structure.md, "3-D variant"): its gauges lie
    in the symmetry plane y = 0 with z up, so the plane's (x, z) columns become
    the report's (r, z) = (x, y) ones, and y the out-of-plane direction."""
    gauge, _, quantity = name.rpartition(".")
    swap = {"stress_yy": "stress_zz", "stress_zz": "stress_yy", "stress_xy": "stress_zx", "stress_zx": "stress_xy"}
    if quantity in swap:
        quantity = swap[quantity]
    elif quantity.endswith("_y"):
        quantity = quantity[:-2] + "_z"
    elif quantity.endswith("_z"):
        quantity = quantity[:-2] + "_y"
    return f"{gauge}.{quantity}" if gauge else name


def generator_parameters(case_path):
    """The `# generator:` line that `camouflet generate` writes into the case header."""
    params = {}
    try:
        with open(case_path) as f:
            for line in f:
                m = re.match(r"#\s*generator:\s*(.*)", line)
                if m:
                    for item in m.group(1).split():
                        key, _, value = item.partition("=")
                        try:
                            params[key] = float(value)
                        except ValueError:
                            params[key] = value  # a word (e.g. a geometry), kept as text
    except OSError:
        pass
    return params


def empirical_averages(camouflet, W, r1, r2):
    """In-structure averages from `camouflet empirical --csv` (rows by attenuation n)."""
    if not camouflet:
        return []
    try:
        text = subprocess.run(
            [camouflet, "empirical", "--charge-mass", str(W), "--coupling", str(F_COUPLING), "--span", str(r1), str(r2),
             "--csv"], check=True, capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"camouflet empirical failed: {e}", file=sys.stderr)
        return []
    return [r for r in csv.DictReader(text.splitlines()) if r["section"] == "in_structure"]


def empirical_range(avg):
    """(V low, V high [m/s], a low, a high [g]) over the attenuation rows; NaN when unknown."""
    v = [float(r["velocity_m_per_s"]) for r in avg]
    a = [float(r["acceleration_g"]) for r in avg]
    nan = float("nan")
    return (min(v, default=nan), max(v, default=nan), min(a, default=nan), max(a, default=nan))


def _peak(values):
    return float(np.nanmax(np.abs(values))) if len(values) else 0.0


def tm5_functions(Z):
    """TM 5-855-1 peak stress as the paper uses it, eqs. (38)-(39), with f = F_COUPLING: (Function 1,
    Function 2) in MPa at scaled distance Z [m/kg^(1/3)]."""
    return F_COUPLING * 15.0 * Z ** -2.5, F_COUPLING * 22.0 * Z ** -2.0


def band_ratio(Z, peak):
    """How far a peak stress [MPa] lies outside the TM-5 band widened by 1.5:
    1 inside; peak / lower edge below it (< 1); peak / upper edge above it (> 1). Function 1 lies above
    Function 2 below Z = 1, so the edges are the smaller and larger of the two."""
    f1, f2 = tm5_functions(Z)
    low, high = min(f1, f2) / 1.5, max(f1, f2) * 1.5
    return peak / low if peak < low else peak / high if peak > high else 1.0


def gauge_names(cols, prefix):
    names = []
    for c in cols:
        g = c.split(".")[0]
        if g.startswith(prefix) and g not in names and "." in c:
            names.append(g)
    return names


def radial_stress(cols, g, centre_z):
    """Normal stress along the ray from the charge centre, compression positive (MPa), and the range R [m]."""
    r0 = cols[g + ".position_x"][0]
    z0 = cols[g + ".position_y"][0]
    R = math.hypot(r0, z0 - centre_z)
    nr, nz = r0 / R, (z0 - centre_z) / R
    s = cols[g + ".stress_xx"] * nr * nr + cols[g + ".stress_yy"] * nz * nz + 2 * cols[g + ".stress_xy"] * nr * nz
    return -s / 1e6, R


def ground_shock_peaks(outdir, burst_depth, charge_mass):
    """{group: [(gauge, Z [m/kg^(1/3)], R [m], peak radial stress [MPa])]} of the soil gauge groups A and B
    (Fig. 8a) in the output folder; groups whose CSV is missing are left out."""
    w3 = charge_mass ** (1.0 / 3.0)
    out = {}
    for name in ("group_A", "group_B"):
        path = os.path.join(outdir, name + ".csv")
        if not os.path.exists(path):
            continue
        _, cols = read_csv(path)
        rows = []
        for g in gauge_names(cols, name[-1]):
            s, R = radial_stress(cols, g, -burst_depth)
            if len(s):
                rows.append((g, R / w3, R, float(np.nanmax(s))))
        out[name] = rows
    return out


def in_structure_peaks(cols):
    """{title: (peak |velocity| [m/s], peak |acceleration| [g], word)} of the front wall and the floor:
    the largest over the set's targets of the raw gauge values (not filtered)."""
    out = {}
    for title, targets, axis, word in STRUCTURE_SETS:
        if not all(f"{g}.velocity_{axis}" in cols for g in targets):
            continue
        vmax = max(_peak(cols[f"{g}.velocity_{axis}"]) for g in targets)
        amax = max(_peak(cols[f"{g}.acceleration_{axis}"] / G) for g in targets)
        out[title] = (vmax, amax, word)
    return out


def member_average_motion(tm, cm):
    """{title: (member, axis, word, peak |velocity| [m/s], (t, acceleration low-passed [m/s^2]) or None)}
    of the front wall's and the floor's member averages (members.csv: the span's mass-weighted mean),
    the acceleration from the velocity's difference quotient (structure_shock.filtered_acceleration)."""
    from structure_shock import filtered_acceleration

    out = {}
    for title, member, axis, word in MEMBER_SETS:
        col = f"{member}.velocity_{axis}"
        if col in cm and len(tm):
            out[title] = (member, axis, word, _peak(cm[col]), filtered_acceleration(tm, cm[col]))
    return out


def interface_stress_peaks(t, cols):
    """(raw, low-passed) peak compressive stress normal to the front wall at target 9 [Pa]
    (Fig. 11: -stress_xx of the soil cell touching the wall), NaN where absent or too coarse."""
    from structure_shock import filtered

    nan = float("nan")
    if "t9.stress_xx" not in cols or not len(t):
        return nan, nan
    normal = -cols["t9.stress_xx"]
    lp = filtered(t, normal)
    return float(np.nanmax(normal)), float(np.nanmax(lp[1])) if lp else nan


def deflections(cols):
    """(front wall, floor) deflection histories [m], or None: the mid-point against the mean of the ends,
    front wall horizontal (t2 against t1/t3), floor vertical (t5 against t3/t6)."""
    if not all(g + ".displacement_x" in cols for g in ("t1", "t2", "t3", "t5", "t6")):
        return None
    wall = cols["t2.displacement_x"] - 0.5 * (cols["t1.displacement_x"] + cols["t3.displacement_x"])
    floor = cols["t5.displacement_y"] - 0.5 * (cols["t3.displacement_y"] + cols["t6.displacement_y"])
    return wall, floor


def final_displacements(cols):
    """{title: largest |displacement| at the last sample [m]} over each set's targets along its axis
    (the permanent displacement when the run has ended after the structure came to rest)."""
    out = {}
    for title, targets, axis, _ in STRUCTURE_SETS:
        series = [cols.get(f"{g}.displacement_{axis}") for g in targets]
        if all(s is not None and len(s) for s in series):
            out[title] = max(abs(float(s[-1])) for s in series)
    return out


def read_vtu(path):
    """ASCII VTK UnstructuredGrid -> (points (n, 3), connectivity per cell, {name: array})."""
    root = ET.parse(path).getroot()
    piece = root.find("UnstructuredGrid/Piece")

    def array(node):
        values = np.array(node.text.split(), dtype=float) if node.text and node.text.strip() else np.zeros(0)
        k = int(node.get("NumberOfComponents", "1"))
        return values.reshape(-1, k) if k > 1 else values

    points = array(piece.find("Points/DataArray"))
    cells = {a.get("Name"): a for a in piece.find("Cells")}
    conn = array(cells["connectivity"]).astype(int)
    offsets = array(cells["offsets"]).astype(int)
    starts = np.concatenate(([0], offsets[:-1]))
    fields = {}
    for group in ("PointData", "CellData"):
        node = piece.find(group)
        if node is not None:
            for a in node:
                fields[a.get("Name")] = array(a)
    return points, [conn[s:e] for s, e in zip(starts, offsets)], fields


def last_snapshots(outdir):
    """{part: file} of the last snapshot in fields.pvd (part 0 mesh, 1 particles) and its time."""
    try:
        root = ET.parse(os.path.join(outdir, "fields.pvd")).getroot()
    except (OSError, ET.ParseError):
        return {}, None
    sets = [(float(d.get("timestep")), int(d.get("part", "0")), d.get("file")) for d in root.iter("DataSet")]
    if not sets:
        return {}, None
    t = max(s[0] for s in sets)
    return {part: os.path.join(outdir, f) for time, part, f in sets if time == t}, t


def _box(gen):
    """The box outline (r1, r2, z_bottom, z_top) and wall thickness from the generator line, or None."""
    if "standoff_m" not in gen:
        return None
    r1 = gen["standoff_m"]
    top = -gen.get("top_depth_m", 0.0)
    return r1, r1 + gen["box_length_m"], top - gen["box_height_m"], top, gen["wall_thickness_m"]


def _member(r, z, box):
    """The structural member of a point of the box (reference position); walls take the corners."""
    r1, r2, zb, zt, t = box
    if r < r1 + t:
        return "front wall"
    if r > r2 - t:
        return "back wall"
    return "roof" if z > zt - t else "floor"


def _reference_snapshot(outdir, gen):
    """The last snapshot in the crater's (r, z) plane: {part: (x, ref, conn, fields, v_up, ref3, in_box)}
    and its time. x and ref (initial positions x - u) are (n, 2) arrays of (r, z), ref3 the initial
    positions in the snapshot's own coordinates; v_up is the upward velocity of each point (zeros
    without a velocity field). In 3-D (the quarter model about the
    charge's vertical axis) r = sqrt(x^2 + y^2), so the crater's ring bins gather every azimuth.
    in_box(centre) says whether an element centre (reference, the snapshot's own coordinates) lies
    in the box's outline: (r, z) in r-z; x, |y| within the half width and z in 3-D."""
    files, t = last_snapshots(outdir)
    raw = {part: read_vtu(path) for part, path in files.items()}
    three_d = bool(gen.get("three_d")) or any(len(p) and np.any(p[:, 2] != 0.0) for p, _, _ in raw.values())
    box = _box(gen)
    half_width = 0.5 * gen.get("box_width_m", 0.0)
    up = 2 if three_d else 1  # the vertical axis: z in 3-D, the second coordinate in r-z

    def in_box(c):
        if box is None:
            return False
        r1, r2, zb, zt, _ = box
        return r1 < c[0] < r2 and zb < c[up] < zt and (not three_d or abs(c[1]) < half_width)

    def plane(p):
        return np.column_stack((np.hypot(p[:, 0], p[:, 1]), p[:, 2])) if three_d else p[:, :2]

    out = {}
    for part, (pts, conn, f) in raw.items():
        u = f.get("displacement", np.zeros_like(pts))
        ref3 = pts - u
        v_up = f["velocity"][:, up] if "velocity" in f else np.zeros(len(pts))
        out[part] = (plane(pts), plane(ref3), conn, f, v_up, ref3, in_box)
    return out, t


def _section_face(ref3, cell):
    """The (x, z) polygon of a hex's face on the symmetry plane y = 0, or None when the hex does not
    touch it. Hex8 lists its bottom face then its top face, so the four plane nodes come unordered:
    sorted by angle about their centre (the faces are convex)."""
    on = [i for i in cell if abs(ref3[i, 1]) < 1e-6]  # a micrometre: x - u carries round-off
    if len(on) != 4:
        return None
    xz = ref3[on][:, [0, 2]]
    c = xz.mean(axis=0)
    return xz[np.argsort(np.arctan2(xz[:, 1] - c[1], xz[:, 0] - c[0]))]


def box_section(outdir, gen):
    """The box's elements in its section at the last snapshot, or None without a mesh snapshot with
    damage: {"time": s, "polygons": [(k, 2) reference (r, z)], "centres": (n, 2), "damage": (n,)}.
    The section is the r-z plane, or in 3-D the symmetry plane y = 0 (the box's mid-width; (x, z)
    taken as (r, z)), through the hexes with a face on it. Reference positions x - u: the section
    stays the undeformed box (its displacements are millimetres)."""
    box = _box(gen)
    files, t = last_snapshots(outdir)
    if box is None or 0 not in files:
        return None
    pts, conn, f = read_vtu(files[0])
    if "damage" not in f:
        return None
    ref3 = pts - f.get("displacement", np.zeros_like(pts))
    three_d = bool(len(pts) and np.any(pts[:, 2] != 0.0))
    r1, r2, zb, zt, _ = box
    polygons, centres, damage = [], [], []
    for c, d in zip(conn, f["damage"]):
        poly = _section_face(ref3, c) if three_d else ref3[c][:, :2]
        if poly is None:
            continue
        r, z = poly.mean(axis=0)
        if r1 < r < r2 and zb < z < zt:  # the box interior has no elements: inside the outline is concrete
            polygons.append(poly)
            centres.append((r, z))
            damage.append(float(d))
    if not polygons:
        return None
    return {"time": t, "polygons": polygons, "centres": np.array(centres), "damage": np.array(damage),
            "box": box, "three_d": three_d}


def front_wall_halves(centres, damage, box):
    """(lower, upper) mean damage of the front wall's elements, split at the box's mid-height by
    element centre: the paper's Fig. 14 finds the heaviest damage in the lower part (the ground
    surface above shifts it down from the centre). NaN for an empty half."""
    r1, r2, zb, zt, _ = box
    mid = 0.5 * (zb + zt)
    front = np.array([_member(r, z, box) == "front wall" for r, z in centres], dtype=bool)
    z = np.asarray(centres)[:, 1] if len(centres) else np.zeros(0)
    lower, upper = damage[front & (z < mid)], damage[front & (z >= mid)]
    return (float(np.mean(lower)) if len(lower) else float("nan"),
            float(np.mean(upper)) if len(upper) else float("nan"))


def structure_damage(outdir, gen):
    """Damage of the box's elements in its section at the last snapshot: {max, member of the max,
    mean per member, front wall's (lower, upper) half means, the section (box_section)}, or {} when
    the run wrote no mesh snapshot. Members by reference position (_member)."""
    sec = box_section(outdir, gen)
    if sec is None:
        return {}
    box = sec["box"]
    members = {}
    best = (-1.0, "")
    for (r, z), d in zip(sec["centres"], sec["damage"]):
        m = _member(r, z, box)
        members.setdefault(m, []).append(d)
        if d > best[0]:
            best = (float(d), m)
    return {"max": best[0], "member": best[1], "mean": {m: float(np.mean(v)) for m, v in members.items()},
            "front_wall_halves": front_wall_halves(sec["centres"], sec["damage"], box), "section": sec}


def crater(outdir, gen):
    """Apparent crater (radius, depth) [m] at the last snapshot, or None.

    The ground is the soil (every element and particle except the explosive and the box) that has not
    been thrown out: a particle that moved more than one layer spacing dz and is now above the original
    surface z = 0 or rising faster than EJECTA_SPEED is ejecta (element nodes stay connected: a heaved
    rim is ground). In radial bins of width dz the ground's
    top is the highest other point; its depression is the bin's reference top (the same points at
    t = 0) minus its current top. The crater is the run of bins from the axis whose depression exceeds
    dz / 2 (empty bins skipped, one shallow bin between deep ones tolerated): its outer edge is the
    apparent radius, its largest depression the apparent depth. dz is the spacing of the two top
    layers of points near the axis (layers closer than d / 1000 are one). Slow material inside the
    bowl counts as ground: without gravity nothing falls back; with it, what has landed below the
    original surface is the fallback a survey of the apparent crater includes. In 3-D r is the distance from the charge's vertical axis and each bin a ring: its top is
    the ring's highest ground, so the radius is where the shallowest azimuth leaves the bowl."""
    box = _box(gen)
    d = gen.get("burst_depth_m")
    snap, _ = _reference_snapshot(outdir, gen)
    if box is None or d is None or not snap:
        return None
    r1 = box[0]
    # The explosive: the material of the element or particle nearest to the charge centre (0, -d) at t = 0.
    candidates = []
    for part, (x, ref, conn, f, _, _, _) in snap.items():
        centres = np.array([ref[c].mean(axis=0) for c in conn]) if part == 0 else ref
        if len(centres):
            k = int(np.argmin(np.hypot(centres[:, 0], centres[:, 1] + d)))
            candidates.append((float(np.hypot(*(centres[k] - (0.0, -d)))), int(f["material"][k])))
    if not candidates:
        return None
    explosive = min(candidates)[1]
    cur, ref0, vz, loose = [], [], [], []
    for part, (x, ref, conn, f, v_up, ref3, in_box) in snap.items():
        mat = f["material"].astype(int)
        if part == 0:
            keep = set()
            for c, m in zip(conn, mat):
                if m != explosive and not in_box(ref3[c].mean(axis=0)):
                    keep.update(int(i) for i in c)
            idx = np.array(sorted(keep), dtype=int)
        else:
            idx = np.nonzero(mat != explosive)[0]
        cur.append(x[idx])
        ref0.append(ref[idx])
        vz.append(v_up[idx])
        loose.append(np.full(len(idx), part != 0))
    cur, ref0, vz, loose = (np.concatenate(a) for a in (cur, ref0, vz, loose))
    near = ref0[ref0[:, 0] < max(d, 1e-9)]
    # Layers closer than d / 1000 are one: x - u carries round-off, and after a dynamic relaxation
    # the reference is the relaxed state, whose layers have settled by microns, unevenly.
    levels = []
    for z in np.unique(near[:, 1])[::-1]:
        if not levels or levels[-1] - z > 1e-3 * max(d, 1e-9):
            levels.append(float(z))
    if len(levels) < 2:
        return None
    dz = levels[0] - levels[1]
    moved = np.hypot(*(cur - ref0).T)
    ground = ~(loose & (moved > dz) & ((cur[:, 1] > 0.0) | (vz > EJECTA_SPEED)))
    nbins = int(math.ceil(r1 / dz))
    ref_top = np.full(nbins, -np.inf)
    cur_top = np.full(nbins, -np.inf)
    # Points on a bin's inner edge (grid lines at multiples of dz) belong to it despite round-off.
    b0 = np.floor(ref0[:, 0] / dz + 1e-6).astype(int)
    b1 = np.floor(cur[:, 0] / dz + 1e-6).astype(int)
    for b, z in zip(b0, ref0[:, 1]):
        if 0 <= b < nbins:
            ref_top[b] = max(ref_top[b], z)
    for b, z, g in zip(b1, cur[:, 1], ground):
        if g and 0 <= b < nbins:
            cur_top[b] = max(cur_top[b], z)
    # Bins with points now and at t = 0 (coarse spacing leaves some empty): (edge, depression).
    drops = [((b + 1) * dz, float(ref_top[b] - cur_top[b])) for b in range(nbins)
             if np.isfinite(ref_top[b]) and np.isfinite(cur_top[b])]
    radius = depth = 0.0
    for k, (edge, drop) in enumerate(drops):
        if drop <= 0.5 * dz:
            # One shallow bin (a point passing through) does not end the crater; two in a row do.
            if k + 1 >= len(drops) or drops[k + 1][1] <= 0.5 * dz:
                break
            continue
        radius, depth = edge, max(depth, drop)
    return radius, depth


def run_metrics(outdir, camouflet=""):
    """Flat {column: value} of a run's headline results (NaN where the output lacks them)."""
    nan = float("nan")
    m = {}
    try:
        with open(os.path.join(outdir, "summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError):
        summary = {}
    e = summary.get("energy_J") or {}
    m["final_time_s"] = summary.get("final_time_s", nan)
    m["stop_reason"] = summary.get("stop_reason", "")
    m["energy_error"] = e.get("relative_error") if e.get("relative_error") is not None else nan
    gen = generator_parameters(os.path.join(outdir, "case.toml"))
    peaks, defl, final, t9 = {}, None, {}, (nan, nan)
    spath = os.path.join(outdir, "structure.csv")
    if os.path.exists(spath):
        ts, cols = read_csv(spath)
        peaks, defl, final = in_structure_peaks(cols), deflections(cols), final_displacements(cols)
        t9 = interface_stress_peaks(ts, cols)
    members = {}
    mpath = os.path.join(outdir, "members.csv")
    if os.path.exists(mpath):
        members = member_average_motion(*read_csv(mpath))
    for title, key in (("front wall", "front_wall"), ("floor", "floor")):
        _, _, _, v, lp = members.get(title, ("", "", "", nan, None))
        m[f"{key}_member_peak_velocity_m_s"] = v
        m[f"{key}_member_filtered_acceleration_g"] = float(np.nanmax(np.abs(lp[1]))) / G if lp else nan
    m["t9_peak_normal_stress_MPa"], m["t9_filtered_normal_stress_MPa"] = (x / 1e6 for x in t9)
    for title, key in (("front wall", "front_wall"), ("floor", "floor")):
        v, a, _ = peaks.get(title, (nan, nan, ""))
        m[f"{key}_peak_velocity_m_s"] = v
        m[f"{key}_peak_acceleration_g"] = a
    m["front_wall_peak_deflection_mm"] = _peak(defl[0]) * 1e3 if defl else nan
    m["floor_peak_deflection_mm"] = _peak(defl[1]) * 1e3 if defl else nan
    m["front_wall_final_displacement_mm"] = final.get("front wall", nan) * 1e3
    m["floor_final_displacement_mm"] = final.get("floor", nan) * 1e3
    dmg = structure_damage(outdir, gen)
    m["max_damage"] = dmg.get("max", nan)
    m["max_damage_member"] = dmg.get("member", "")
    m["front_wall_mean_damage"] = dmg.get("mean", {}).get("front wall", nan)
    m["front_wall_lower_mean_damage"], m["front_wall_upper_mean_damage"] = dmg.get("front_wall_halves", (nan, nan))
    others = [v for k, v in dmg.get("mean", {}).items() if k != "front wall"]
    m["other_members_mean_damage"] = max(others) if others else nan
    cr = crater(outdir, gen)
    m["crater_radius_m"], m["crater_depth_m"] = cr if cr else (nan, nan)
    if gen:
        avg = empirical_averages(camouflet, gen["charge_mass_kg"], gen["standoff_m"],
                                 gen["standoff_m"] + gen["box_length_m"])
        (m["tm5_velocity_low_m_s"], m["tm5_velocity_high_m_s"], m["tm5_acceleration_low_g"],
         m["tm5_acceleration_high_g"]) = empirical_range(avg)
    else:
        m["tm5_velocity_low_m_s"] = m["tm5_velocity_high_m_s"] = nan
        m["tm5_acceleration_low_g"] = m["tm5_acceleration_high_g"] = nan
    return m
