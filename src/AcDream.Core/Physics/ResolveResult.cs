using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Outcome of <see cref="PhysicsEngine.Resolve(Vector3, uint, Vector3, float)"/>.
/// </summary>
/// <param name="Position">Resolved position in the engine's world frame, metres. Never NaN.</param>
/// <param name="CellId">Full cell id (<c>0xXXYYCCCC</c>) the mover ends up in: outdoor 0x0001..0x0040 or indoor 0x0100..0xFFFD.</param>
/// <param name="IsOnGround">
/// True exactly when <see cref="Position"/> stands on terrain or a floor: its Z within
/// <see cref="PhysicsConstants.GroundTolerance"/> (0.2 mm) of the terrain, or of the floor of
/// <see cref="CellId"/> nearest it, under its XY, or of an object's floor there (the ground that
/// <see cref="PhysicsEngine.TryGetGround(Vector3, uint, float, out float, out Vector3, out uint)"/> finds);
/// with <see cref="MovementOptions.Footing"/>, also of a floor that holds the body within its support
/// reach (<see cref="PhysicsConstants.SupportReach"/> of its radius past the floor's edge) where none
/// is under its centre. False when the mover is above the ground (nothing under it, a refused move in
/// mid-air, or airborne with step down): the caller's gravity should act. The one exception is a
/// mover held because its landblock is not loaded: true, so it does not fall.
/// </param>
public readonly record struct ResolveResult(
    Vector3 Position,
    uint CellId,
    bool IsOnGround)
{
    // IsOnGround (bit 0) and Outcome (the bits above) share one field, so the struct has four fields
    // and the JIT keeps it in registers (promotes it): with five, every answer was copied through
    // memory with one wide load after narrow stores, a store-forwarding stall on every Resolve.
    private readonly int _groundAndOutcome = IsOnGround ? 1 : 0;

    /// <summary>
    /// True exactly when <see cref="Position"/> stands on terrain or a floor: its Z within
    /// <see cref="PhysicsConstants.GroundTolerance"/> (0.2 mm) of the terrain, or of the floor of
    /// <see cref="CellId"/> nearest it, under its XY, or of an object's floor there (the ground that
    /// <see cref="PhysicsEngine.TryGetGround(Vector3, uint, float, out float, out Vector3, out uint)"/> finds);
    /// with <see cref="MovementOptions.Footing"/>, also of a floor that holds the body within its support
    /// reach (<see cref="PhysicsConstants.SupportReach"/> of its radius past the floor's edge) where none
    /// is under its centre. False when the mover is above the ground (nothing under it, a refused move in
    /// mid-air, or airborne with step down): the caller's gravity should act. The one exception is a
    /// mover held because its landblock is not loaded: true, so it does not fall.
    /// </summary>
    public bool IsOnGround
    {
        get => (_groundAndOutcome & 1) != 0;
        init => _groundAndOutcome = (_groundAndOutcome & ~1) | (value ? 1 : 0);
    }

    /// <summary>
    /// Why the mover ended where it did: moved, held, or which refusal stopped it. With swept moves,
    /// a move stopped part way reports the refusal that stopped it (and the last accepted position).
    /// </summary>
    /// <value><see cref="ResolveOutcome.Moved"/> by default.</value>
    public ResolveOutcome Outcome
    {
        get => (ResolveOutcome)(_groundAndOutcome >> 1);
        init => _groundAndOutcome = (_groundAndOutcome & 1) | ((int)value << 1);
    }

    /// <summary>
    /// Where a surface stopped or turned the move, its unit normal (world axes, pointing towards the
    /// mover's side): the terrain's under a step or slope too steep (and for a body slid along a
    /// slope's contour), a doorway wall's when the move crossed a doorway's plane beside its opening,
    /// and with a body the last wall it touched (horizontal) when it slid or was stopped. Zero
    /// otherwise (moved, held, unloaded land, the edge of the world, a floor edge, a building's
    /// outer wall found by the doors-only rule).
    /// </summary>
    public Vector3 SurfaceNormal { get; init; }

    /// <summary>Whether the move was refused (the mover kept its XY): an outcome other than moved, slid, held or <see cref="ResolveOutcome.Ceiling"/>.</summary>
    public bool IsRefused => Outcome > ResolveOutcome.Held && Outcome < ResolveOutcome.Ceiling;
}
