"""Reading binary STL files (as softopt writes them) and drawing them
offscreen with matplotlib: shared by scripts/render_stl and
scripts/render_mold. Needs Debian's python3-numpy and python3-matplotlib.
"""
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

BLUE = (0.55, 0.72, 0.9)


def read_triangles(path):
    """The triangles of a binary STL, shape (n, 3, 3), as stored (mm)."""
    with open(path, "rb") as f:
        f.seek(80)
        n = int(np.frombuffer(f.read(4), dtype="<u4")[0])
        record = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)),
                           ("attr", "<u2")])
        data = np.frombuffer(f.read(n * record.itemsize), dtype=record)
    return data["v"].astype(float)


def read_stl(path):
    """The triangles in plot coordinates (y, z, x): the actuator axis x
    points up."""
    return read_triangles(path)[:, :, [1, 2, 0]]


def draw(ax, parts, elevation, azimuth):
    """Draws parts, a list of (triangles, rgb) or one triangle array, lit
    from a fixed direction, with equal axes around all of them."""
    if isinstance(parts, np.ndarray):
        parts = [(parts, BLUE)]
    light = np.array([0.4, -0.5, 0.75])
    light /= np.linalg.norm(light)
    for triangles, rgb in parts:
        normals = np.cross(triangles[:, 1] - triangles[:, 0],
                           triangles[:, 2] - triangles[:, 0])
        normals /= np.linalg.norm(normals, axis=1)[:, None] + 1e-300
        shade = 0.35 + 0.65 * np.abs(normals @ light)
        ax.add_collection3d(Poly3DCollection(
            triangles, facecolors=np.outer(shade, rgb), edgecolors="none"))
    points = np.concatenate([t.reshape(-1, 3) for t, _ in parts])
    lo, hi = points.min(0), points.max(0)
    center, half = (lo + hi) / 2, (hi - lo).max() / 2
    for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), center):
        set_lim(c - half, c + half)
    ax.view_init(elev=elevation, azim=azimuth)
    ax.set_axis_off()
