using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>The call that also says what a move met (<see cref="MoveReport"/>), on the same move as <c>Resolve</c>.</summary>
public sealed partial class PhysicsEngine
{
    /// <summary>
    /// <see cref="Resolve(Vector3, uint, Vector3, float, in MovementOptions)"/>, and what the move met: the floor the
    /// answer stands on and the wall, shell or cylinder that stopped or slid it (see <see cref="MoveReport"/>). The
    /// answer is bit for bit that of the call without the report; the report costs only the calls that ask for it.
    /// </summary>
    /// <param name="currentPos">Where the mover's feet are, world metres.</param>
    /// <param name="currentCellId">The cell the mover is in (<c>0xXXYYCCCC</c>).</param>
    /// <param name="delta">The intended move, world metres; its Z is ignored unless <see cref="MovementOptions.Vertical"/> (with a body) moves the body up and down by it.</param>
    /// <param name="stepUpHeight">Highest rise one move (one sub-step when sweeping) may climb, metres, ≥ 0.</param>
    /// <param name="options">The effects to simulate; see <see cref="MovementOptions"/>.</param>
    /// <param name="report">What the move met.</param>
    /// <exception cref="ArgumentException">As the four-argument call.</exception>
    public ResolveResult Resolve(
        Vector3 currentPos,
        uint currentCellId,
        Vector3 delta,
        float stepUpHeight,
        in MovementOptions options,
        out MoveReport report)
    {
        MoveQuery.Validate(currentPos, currentCellId, delta, stepUpHeight);
        var lands = new Neighbourhood(_registry);
        return _movers.Any && lands.Meet(_movers, in _frame, currentPos, currentCellId, MoverReach(delta, in options), 0)
            ? HeldReported(ref lands, currentPos, currentCellId, delta, stepUpHeight, in options, out report)
            : Reported(ref lands, currentPos, currentCellId, delta, stepUpHeight, in options, out report);
    }

    /// <summary>
    /// <see cref="Resolve(Vector3, uint, Vector3, float, in MovementOptions)"/> for a registered mover: the mover
    /// <paramref name="moverId"/> is not met by its own move, and the rules of who blocks whom read its committed state
    /// (see <see cref="MoverState"/>). An id not committed (or 0) moves as an unregistered object: nothing skipped.
    /// </summary>
    /// <param name="currentPos">Where the mover's feet are, world metres.</param>
    /// <param name="currentCellId">The cell the mover is in (<c>0xXXYYCCCC</c>).</param>
    /// <param name="delta">The intended move, world metres (see the call without the id).</param>
    /// <param name="stepUpHeight">Highest rise one move (one sub-step when sweeping) may climb, metres, ≥ 0.</param>
    /// <param name="options">The effects to simulate; see <see cref="MovementOptions"/>.</param>
    /// <param name="moverId">The id of the mover that moves (<see cref="Movers"/>).</param>
    /// <exception cref="ArgumentException">As the four-argument call.</exception>
    public ResolveResult Resolve(
        Vector3 currentPos,
        uint currentCellId,
        Vector3 delta,
        float stepUpHeight,
        in MovementOptions options,
        uint moverId)
        => Moved(currentPos, currentCellId, delta, stepUpHeight, in options, moverId);

    /// <summary>
    /// <see cref="Resolve(Vector3, uint, Vector3, float, in MovementOptions, uint)"/>, what the move met
    /// (<see cref="MoveReport"/>; a mover that stopped it is <see cref="SurfaceKind.Mover"/> with its id), and every
    /// mover it touched, blocking or not: the movers met (not the mover itself, not one both Ethereal and
    /// IgnoreCollisions) whose walls the mover's disc (its body's radius, or a point) comes within
    /// <see cref="PhysicsConstants.TouchReach"/> of along the straight line from its start to the answer, over the height
    /// from its lower feet to its higher head (a point: its feet to its step up), and the one that stopped it. The answer is bit for bit that of the
    /// call without them; they cost only the calls that ask.
    /// </summary>
    /// <param name="currentPos">Where the mover's feet are, world metres.</param>
    /// <param name="currentCellId">The cell the mover is in (<c>0xXXYYCCCC</c>).</param>
    /// <param name="delta">The intended move, world metres (see the call without the id).</param>
    /// <param name="stepUpHeight">Highest rise one move (one sub-step when sweeping) may climb, metres, ≥ 0.</param>
    /// <param name="options">The effects to simulate; see <see cref="MovementOptions"/>.</param>
    /// <param name="moverId">The id of the mover that moves, or 0.</param>
    /// <param name="touched">Where the ids of the movers touched are written, in the order the line from the start to the answer first touches them (one overlapped at the start first, the one that stopped the move last; equal fractions in the order the committed state files them): the same for the same state and call.</param>
    /// <param name="touchedCount">How many movers were touched; when more than <paramref name="touched"/> holds, the first touched that fit are written: the first 64 in the order touched, any more after them in the order the committed state files them.</param>
    /// <param name="report">What the move met.</param>
    /// <exception cref="ArgumentException">As the four-argument call.</exception>
    public ResolveResult Resolve(
        Vector3 currentPos,
        uint currentCellId,
        Vector3 delta,
        float stepUpHeight,
        in MovementOptions options,
        uint moverId,
        Span<uint> touched,
        out int touchedCount,
        out MoveReport report)
    {
        MoveQuery.Validate(currentPos, currentCellId, delta, stepUpHeight);
        var lands = new Neighbourhood(_registry);
        if (!(_movers.Any && lands.Meet(_movers, in _frame, currentPos, currentCellId, MoverReach(delta, in options), moverId)))
        {
            touchedCount = 0; // no mover near
            return Reported(ref lands, currentPos, currentCellId, delta, stepUpHeight, in options, out report);
        }

        try
        {
            ResolveResult result = Reported(ref lands, currentPos, currentCellId, delta, stepUpHeight, in options, out report);
            touchedCount = Touches.Along(
                _frame, ref lands, currentPos, currentCellId, in result, stepUpHeight, options.Body, report.Wall.Kind == SurfaceKind.Mover ? report.Wall.Id : 0, touched);
            return result;
        }
        finally
        {
            lands.Release();
        }
    }

    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: a call with no mover near has no handler to set up
    private ResolveResult HeldReported(
        ref Neighbourhood lands, Vector3 currentPos, uint currentCellId, Vector3 delta, float stepUpHeight, in MovementOptions options, out MoveReport report)
    {
        try
        {
            return Reported(ref lands, currentPos, currentCellId, delta, stepUpHeight, in options, out report);
        }
        finally
        {
            lands.Release();
        }
    }

    private ResolveResult Reported(
        ref Neighbourhood lands, Vector3 currentPos, uint currentCellId, Vector3 delta, float stepUpHeight, in MovementOptions options, out MoveReport report)
    {
        var query = new MoveQuery(ref lands, currentPos, currentCellId, new Vector2(delta.X, delta.Y), stepUpHeight, in options);
        lands.Reporting = true;
        ResolveResult result = Move(ref query, in options, delta.Z);
        report = Report(ref lands, in result, new SurfaceContact(lands.MetKind, lands.MetId, default), in options);
        return result;
    }

    /// <summary>
    /// What the move that answered <paramref name="result"/> met: the ground the answer stands on (the one ground
    /// probe, at the answer's feet: what standing there gives again), and <paramref name="wall"/> as the move recorded
    /// it when its outcome is a wall's, an edge's or a ceiling's (with the answer's normal); with footing, the floor under the
    /// body's footprint that holds it where the ground under its centre does not.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private MoveReport Report(ref Neighbourhood lands, in ResolveResult result, SurfaceContact wall, in MovementOptions options)
    {
        bool walled = result.Outcome is ResolveOutcome.Wall or ResolveOutcome.OuterWall or ResolveOutcome.Edge or ResolveOutcome.Ceiling
            || (result.Outcome == ResolveOutcome.Slid && result.SurfaceNormal.Z == 0f);
        SurfaceContact met = walled && wall.Kind != SurfaceKind.None ? wall with { Normal = result.SurfaceNormal } : default;
        SurfaceContact floor = default;
        if (result.IsOnGround && result.Outcome != ResolveOutcome.Held
            && Locator.TryFind(_frame, ref lands, result.Position, result.CellId, out Place place))
        {
            Ground.TryUnder(ref lands, in place, result.Position.Z, PhysicsConstants.GroundTolerance, out float z, out floor);
            if (z != result.Position.Z && options.InThreeD && options.Footing)
            {
                // Held by a floor under its footprint, not the ground under its centre.
                const float tolerance = PhysicsConstants.GroundTolerance;
                float reach = options.Body!.Value.Radius * PhysicsConstants.SupportReach;
                Support support = Supports.Highest(ref lands, in place, -1, place.Local, reach, result.Position.Z - tolerance, result.Position.Z + tolerance);
                floor = support.Found ? support.Floor : floor;
            }
        }

        return new MoveReport(floor, met);
    }
}
