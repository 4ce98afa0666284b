using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// One cast asked of the engine (<see cref="PhysicsEngine.Cast(in CastRequest)"/>): a sphere (a ray at radius 0) from a
/// point in a cell along a displacement, said as a move says it (<see cref="MoveRequest"/>): where it starts, its
/// cell, the delta; the mover id beside them.
/// </summary>
/// <remarks>Built as <c>new CastRequest(from, cellId, to - from) { Options = new CastOptions(0.3f), MoverId = id }</c>.</remarks>
/// <param name="From">Where the sphere's centre starts, world metres.</param>
/// <param name="FromCellId">The cell <paramref name="From"/> is in (<c>0xXXYYCCCC</c>); outdoors any outdoor number, 0 included, is recomputed from the position.</param>
/// <param name="Delta">The path of the centre, world metres: it ends at <paramref name="From"/> + <paramref name="Delta"/> (rounded to floats); zero meets nothing.</param>
public readonly record struct CastRequest(Vector3 From, uint FromCellId, Vector3 Delta)
{
    /// <summary>The sphere's radius and what it ignores (<see cref="CastOptions"/>); default: a ray that meets everything.</summary>
    public CastOptions Options { get; init; }

    /// <summary>A registered mover the cast ignores (the caster itself: the camera's player, the pointer's avatar); 0 (the default): none.</summary>
    public uint MoverId { get; init; }
}
