"""Smoke and fire domains (a mesh with a Fluid modifier of type Domain, Gas) as Cycles 3.4
renders them: a volume over the box the simulation's grids fill, shaded by those grids under
Cycles' attribute names (density, flame, heat, temperature, color). Cycles reads the grids from
the evaluated modifier (intern/cycles/blender/volume.cpp, BlenderSmokeLoader); the add-on reads
the same arrays and writes them as one OpenVDB file per domain, which glint reads like a Volume
object's file.

    gas_domain(ob) -> FluidDomainSettings or None
    texture_space(ob) -> (lo, hi), the box the grids fill
    write_grids(vdb, domain, lo, hi, path) -> number of grids written (0: no smoke)

Needs pyopenvdb (bundled with Blender's own builds; Debian's package python3-openvdb).
"""

import numpy as np

# Cycles' attribute name -> the domain's array, and its channels.
_GRIDS = (("density", "density_grid", 1), ("flame", "flame_grid", 1),
          ("heat", "heat_grid", 1), ("temperature", "temperature_grid", 1),
          ("color", "color_grid", 4))


def gas_domain(ob):
    """The gas domain settings of `ob` (evaluated, so its grids are the frame's), as Cycles'
    object_fluid_gas_domain_find finds them: the first Fluid modifier that is a gas domain,
    shown or not."""
    for mod in getattr(ob, "modifiers", ()):
        if mod.type == 'FLUID' and mod.fluid_type == 'DOMAIN' and \
                mod.domain_settings.domain_type == 'GAS':
            return mod.domain_settings
    return None


def openvdb_module():
    """pyopenvdb, or None where this Blender has none."""
    try:
        import pyopenvdb
    except ImportError:
        return None
    return pyopenvdb


def grid_resolution(domain, full=True):
    """The cells of the frame's grids along x, y, z: the adaptive domain's current box, times
    the noise's upscaling for all grids but heat (and velocity), which Mantaflow keeps at the
    base resolution (full=False)."""
    res = tuple(domain.domain_resolution)
    if full and domain.use_noise:
        res = tuple(r * domain.noise_scale for r in res)
    return res


def _read(domain, attr, count):
    values = getattr(domain, attr)
    if len(values) != count:
        return None
    out = np.empty(count, dtype=np.float32)
    try:
        values.foreach_get(out)
    except (AttributeError, TypeError):
        out[:] = values[:]
    return out


def write_grids(vdb, domain, lo, hi, path):
    """Writes the domain's grids at this frame to `path`: voxel (i, j, k) of a grid of n cells
    along each axis covers [lo + i (hi - lo) / n, lo + (i + 1) (hi - lo) / n] in the domain's
    object space, as Cycles maps the smoke textures over the evaluated mesh's bounds. Returns
    how many grids were written; 0 when the frame has no smoke (nothing written)."""
    grids = []
    for name, attr, channels in _GRIDS:
        res = grid_resolution(domain, full=name != "heat")
        cells = res[0] * res[1] * res[2]
        flat = _read(domain, attr, cells * channels) if cells > 0 else None
        if flat is None:
            continue
        step = [(h - l) / n for l, h, n in zip(lo, hi, res)]
        matrix = [[step[0], 0, 0, 0], [0, step[1], 0, 0], [0, 0, step[2], 0],
                  [lo[0], lo[1], lo[2], 1]]  # OpenVDB's row-vector convention
        # Mantaflow's order: x fastest, then y, then z; OpenVDB's arrays index [x][y][z].
        a = flat.reshape(res[2], res[1], res[0], channels).transpose(2, 1, 0, 3)
        if channels == 1:
            grid = vdb.FloatGrid()
            grid.copyFromArray(np.ascontiguousarray(a[..., 0]))
        else:
            grid = vdb.Vec3SGrid()
            grid.copyFromArray(np.ascontiguousarray(a[..., :3]))
        grid.name = name
        grid.transform = vdb.createLinearTransform(matrix)
        grids.append(grid)
    # Before the simulation (or a replay cache jumped to this frame) density and flame are
    # empty; the colour grid holds the flow colour everywhere even then.
    if not any(g.activeVoxelCount() for g in grids if g.name in ("density", "flame")):
        return 0
    vdb.write(path, grids=grids)
    return len(grids)


def texture_space(ob):
    """The box Cycles maps the smoke grids over: the evaluated domain mesh's texture space
    (its bounds unless the user set one), as min and max corners in object space."""
    me = ob.data
    loc, size = me.texspace_location, me.texspace_size
    return [loc[k] - size[k] for k in range(3)], [loc[k] + size[k] for k in range(3)]
