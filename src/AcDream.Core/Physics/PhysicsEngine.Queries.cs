using System.Numerics;

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
}
