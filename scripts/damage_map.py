"""The concrete damage map of `camouflet report` (cf. Fig. 14 of Wang, Lu, Hao,
Chong 2005): damage 0..1 of the box's elements at the last snapshot over the
box's section (run_metrics.box_section), the whole box beside its front wall
enlarged, with the front wall's lower half outlined, where the paper finds the
heaviest damage. matplotlib and NumPy only."""
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.patches import Rectangle

CMAP = "magma_r"  # light where undamaged, so the damaged concrete stands out against the page


def _draw(ax, section, box, norm, mark_label):
    r1, r2, zb, zt, t = box
    mesh = PolyCollection(section["polygons"], array=section["damage"], cmap=CMAP, norm=norm,
                          edgecolors="0.75", linewidths=0.15)
    ax.add_collection(mesh)
    ax.add_patch(Rectangle((r1, zb), t, 0.5 * (zt - zb), fill=False, ec="C0", lw=1.8, ls="--",
                           label=mark_label))
    ax.set_aspect("equal")
    ax.grid(False)
    return mesh


def damage_map(section, lower_upper):
    """The figure: (matplotlib figure, caption). section from run_metrics.box_section, lower_upper
    the front wall's (lower, upper) half means (run_metrics.front_wall_halves)."""
    box, three_d = section["box"], section["three_d"]
    r1, r2, zb, zt, t = box
    horizontal = "x" if three_d else "r"
    norm = plt.Normalize(0.0, 1.0)
    # Constrained layout keeps the colorbar shared by both panels clear of them (tight_layout does not).
    fig, (whole, wall) = plt.subplots(1, 2, figsize=(11, 3.6), layout="constrained",
                                      gridspec_kw={"width_ratios": [5.0, 1.3]})
    lower, upper = lower_upper
    mark = f"front wall, lower half (mean {lower:.3g}; upper half {upper:.3g})"
    mesh = _draw(whole, section, box, norm, mark)
    pad = 0.1 * (zt - zb)
    whole.set_xlim(r1 - pad, r2 + pad)
    whole.set_ylim(zb - pad, zt + pad)
    whole.set_xlabel(f"{horizontal} [m] (charge at {horizontal} = 0, to the left)")
    whole.set_ylabel("z [m]")
    whole.legend(loc="center", fontsize=9)  # in the hollow of the box, clear of the concrete
    whole.set_title("the box's section" + (" in the symmetry plane y = 0" if three_d else ""))
    _draw(wall, section, box, norm, None)
    wall.set_xlim(r1 - t, r1 + 3.0 * t)
    wall.set_ylim(zb - 0.5 * t, zt + 0.5 * t)
    wall.set_xlabel(f"{horizontal} [m]")
    wall.set_title("front wall, enlarged")
    wall.set_xticks([r1, r1 + t])  # its faces; more ticks overlap on a panel this narrow
    cbar = fig.colorbar(mesh, ax=[whole, wall], fraction=0.04, pad=0.02)
    cbar.set_label("damage D [-]")
    fig.suptitle(f"Concrete damage at t = {section['time'] * 1e3:.1f} ms (cf. Fig. 14)")
    where = "the symmetry plane y = 0 (the box's mid-width)" if three_d else "the r–z section"
    caption = (f"Damage of the box's concrete (0 intact, 1 fully damaged) at the last snapshot, "
               f"t = {section['time'] * 1e3:.1f} ms, over {where} of the undeformed box; right, the front "
               f"wall enlarged. Dashed: the front wall's lower half, mean damage {lower:.3g} against "
               f"{upper:.3g} in its upper half.")
    return fig, caption
