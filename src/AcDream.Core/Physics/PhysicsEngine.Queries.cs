using System.Numerics;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Point;

namespace AcDream.Core.Physics;

/// <summary>The host queries: world and landblock frames, and the ground under a position, on the same locator and surfaces as <c>Resolve</c>.</summary>
public sealed partial class PhysicsEngine
{
    /// <summary>
    /// World position (metres, Z = 0) of the south-west corner of a landblock: add landblock-local
    /// coordinates to it to get world coordinates.
    /// </summary>
    /// <param name="landblockId">Any id of the landblock (its low 16 bits are ignored).</param>
    public Vector3 GetLandblockOrigin(uint landblockId) => new(_frame.Origin(CellIds.LandblockX(landblockId), CellIds.LandblockY(landblockId)), 0f);

    /// <summary>The landblock (<c>0xXXYYFFFF</c>) under a world position, metres; positions off the world clamp to its nearest edge.</summary>
    /// <exception cref="ArgumentException">A coordinate is NaN.</exception>
    public uint LandblockAt(Vector3 worldPosition)
    {
        if (float.IsNaN(worldPosition.X) || float.IsNaN(worldPosition.Y))
        {
            throw new ArgumentException($"world position {worldPosition} must not be NaN.", nameof(worldPosition));
        }

        return _frame.LandblockAt(worldPosition);
    }

    /// <summary>A landblock-local position (metres) of the landblock of <paramref name="id"/> (any id of it), in world metres.</summary>
    public Vector3 ToWorld(uint id, Vector3 landblockLocal) => GetLandblockOrigin(id) + landblockLocal;

    /// <summary>A world position (metres) in the landblock-local frame of the landblock of <paramref name="id"/> (any id of it).</summary>
    public Vector3 ToLandblockLocal(uint id, Vector3 world) => world - GetLandblockOrigin(id);

    /// <summary>
    /// The ground under a world position: for an outdoor <paramref name="cellId"/> (or 0) the terrain
    /// of the landblock under the position; for an indoor one, that cell's floor nearest the position's
    /// Z; in either case raised to an object's floor that lies above it and no higher than the position's
    /// Z (the step-height overload with a step of 0). The same surfaces, sampled the same way, as <c>Resolve</c>.
    /// </summary>
    /// <param name="worldPosition">World metres; Z is the reference for stacked floors.</param>
    /// <param name="cellId">The cell the position is in (<c>0xXXYYCCCC</c>), or an outdoor id / 0 for the terrain.</param>
    /// <param name="groundZ">The ground's Z, metres.</param>
    /// <param name="normal">The ground's unit normal (pointing up).</param>
    /// <returns>False when the landblock is not loaded, or neither a floor of the cell nor an object's floor lies under the position.</returns>
    /// <exception cref="ArgumentException">A coordinate is not finite, or the indoor cell is not in its loaded landblock (as <c>Resolve</c>).</exception>
    public bool TryGetGround(Vector3 worldPosition, uint cellId, out float groundZ, out Vector3 normal) =>
        TryGetGround(worldPosition, cellId, 0f, out groundZ, out normal, out _);

    /// <summary>
    /// The ground a mover with its feet at <paramref name="worldPosition"/> and step
    /// <paramref name="stepUpHeight"/> stands on, as <c>Resolve</c> samples it: the terrain (outdoors) or
    /// the cell's floor nearest the feet (indoors), or an object's floor above that and no more than the
    /// step above the feet; and which object's floor it is.
    /// </summary>
    /// <param name="worldPosition">World metres; Z is the feet.</param>
    /// <param name="cellId">The cell the position is in, or an outdoor id / 0.</param>
    /// <param name="stepUpHeight">The mover's step, metres, ≥ 0.</param>
    /// <param name="groundZ">The ground's Z, metres.</param>
    /// <param name="normal">The ground's unit normal (pointing up).</param>
    /// <param name="objectId">The GfxObj or Setup id of the object whose floor it is; 0 for the terrain or a cell's floor.</param>
    /// <returns>False when the landblock is not loaded, or nothing lies under the position.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The step is not finite or is negative (as <c>Resolve</c>).</exception>
    /// <exception cref="ArgumentException">A coordinate is not finite, or the indoor cell is not in its loaded landblock (as <c>Resolve</c>).</exception>
    public bool TryGetGround(Vector3 worldPosition, uint cellId, float stepUpHeight, out float groundZ, out Vector3 normal, out uint objectId)
    {
        if (!Geometry.IsFinite(worldPosition))
        {
            throw new ArgumentException($"world position {worldPosition} must be finite.", nameof(worldPosition));
        }

        if (!(stepUpHeight >= 0f) || !float.IsFinite(stepUpHeight))
        {
            throw new ArgumentOutOfRangeException(nameof(stepUpHeight), stepUpHeight, "stepUpHeight must be a finite height ≥ 0 m."); // as Resolve
        }

        (groundZ, normal, objectId) = (0f, default, 0u);
        var lands = new Neighbourhood(_registry);
        if (!Locator.TryFind(_frame, ref lands, worldPosition, cellId, out Place place, nameof(cellId))
            || !Ground.TryUnder(ref lands, in place, worldPosition.Z, stepUpHeight, out groundZ, out SurfaceContact floor))
        {
            return false;
        }

        normal = floor.Normal;
        objectId = floor.Kind == SurfaceKind.ObjectFloor ? floor.Id : 0u;
        return true;
    }

    /// <summary>
    /// Which cell holds <paramref name="position"/>: searched through portals from <paramref name="hintCellId"/> (the cell of
    /// a point near it: the player's for the camera's eye), else the outdoor cell under it.
    /// </summary>
    /// <remarks>
    /// An indoor cell holds a point when one of its floors lies under the point's XY at or below it (within
    /// <see cref="PhysicsConstants.GroundTolerance"/>) and the point is not above the cell's walls; of the cells that do,
    /// reached through portals from the hint (from an outdoor hint: from the cells with a door to the outdoors in the
    /// point's landblock), at most <see cref="PhysicsConstants.MaxCellVisits"/> of them, the one whose floor is highest. A
    /// point over land not loaded is in the outdoor cell its position names. Allocates nothing.
    /// </remarks>
    /// <param name="position">The point, world metres.</param>
    /// <param name="hintCellId">A cell near the point (<c>0xXXYYCCCC</c>; any outdoor number, 0 included, for outdoors).</param>
    /// <returns>The cell's id, <c>0xXXYYCCCC</c>.</returns>
    /// <exception cref="ArgumentException">The position is not finite, the hint is not a cell of the world, or an indoor hint is not in its loaded landblock.</exception>
    public uint FindCell(Vector3 position, uint hintCellId)
    {
        if (!Geometry.IsFinite(position))
        {
            throw new ArgumentException($"position {position} (hint 0x{hintCellId:X8}) must be finite.", nameof(position));
        }

        if (!CellIds.IsCellOfTheWorld(hintCellId))
        {
            throw new ArgumentException($"hintCellId 0x{hintCellId:X8} is not a cell of the world (0x0000..0x0040 outdoors, 0x0100..0xFFFD indoors, landblock X and Y below 0xFF).", nameof(hintCellId));
        }

        var lands = new Neighbourhood(_registry);
        return CellFinder.Find(in _frame, ref lands, position, hintCellId);
    }
}
