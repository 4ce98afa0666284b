using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>The call that also says what a move met (<see cref="MoveReport"/>), on the same move as <c>Resolve</c>.</summary>
public sealed partial class PhysicsEngine
{
    /// <summary>
    /// The general move: <see cref="Resolve(Vector3, uint, Vector3, float, in MovementOptions)"/> as the request says,
    /// as the mover <see cref="MoveRequest.MoverId"/>, with what the move met when asked and the movers it touched.
    /// </summary>
    /// <remarks>
    /// <para>
    /// The answer (<see cref="MoveResult.Answer"/>) is bit for bit that of the call with the same options: the report,
    /// the mover id's skip and the touches change nothing of it. A registered mover's move does not meet its own walls,
    /// and the rules of who blocks whom read its committed state (see <see cref="MoverState"/>); an id not committed (or
    /// 0) moves as an unregistered object.
    /// </para>
    /// <para>
    /// Touched movers: every committed mover whose walls the answer's path comes within
    /// <see cref="PhysicsConstants.TouchReach"/> of (blocking or not: an Ethereal door walked through is touched), each
    /// once, in the order met along the path from the start to the answer; the first ones, up to the span's length, are
    /// written into <paramref name="touched"/>, and <see cref="MoveResult.TouchedCount"/> says how many there were. With
    /// no mover near, 0 and nothing is written.
    /// </para>
    /// </remarks>
    /// <param name="request">The move: position (world metres), cell, delta, step, options, mover id, whether to report.</param>
    /// <param name="touched">Where to write the ids of the movers touched; empty (the default): touches are not looked for, and the count is 0.</param>
    /// <exception cref="ArgumentException">As the four-argument call, named <c>request</c> with the field.</exception>
#pragma warning disable RS0027 // (the spec's four-argument Resolve has no optional parameter to clash with; one general call reads best with the span optional)
    public MoveResult Resolve(in MoveRequest request, Span<uint> touched = default)
#pragma warning restore RS0027
    {
        MoveResult result = Answer(in request, touched);
        _recorder?.Resolved(in request, touched, in result);
        return result;
    }

    /// <summary>The general move's answer (the public call's, before its recorder sees it).</summary>
    private MoveResult Answer(in MoveRequest request, Span<uint> touched)
    {
        MoveQuery.Validate(in request);
        MovementOptions options = request.Options;
        var lands = new Neighbourhood(_registry);
        long commit = _movers.CommitNumber;
        if (!(_movers.Any && lands.Meet(_movers, in _frame, request.Position, request.CellId, MoverReach(request.Delta, in options), request.MoverId)))
        {
            return request.WithReport
                ? new MoveResult(Reported(ref lands, in request, out MoveReport report), report, 0, commit)
                : new MoveResult(Moved(ref lands, in request), default, 0, commit);
        }

        try
        {
            commit = lands.Movers!.Commit;
            if (touched.IsEmpty && !request.WithReport)
            {
                return new MoveResult(Moved(ref lands, in request), default, 0, commit);
            }

            ResolveResult result = Reported(ref lands, in request, out MoveReport report);
            int count = Touches.Along(
                _frame, ref lands, request.Position, request.CellId, in result, request.StepUpHeight, options.Body,
                report.Wall.Kind == SurfaceKind.Mover ? report.Wall.Id : 0, touched);
            return new MoveResult(result, request.WithReport ? report : default, count, commit);
        }
        finally
        {
            lands.Release();
        }
    }

    /// <summary>The request's move, no report.</summary>
    private ResolveResult Moved(ref Neighbourhood lands, in MoveRequest request)
    {
        MovementOptions options = request.Options;
        var query = new MoveQuery(ref lands, request.Position, request.CellId, new Vector2(request.Delta.X, request.Delta.Y), request.StepUpHeight, in options);
        return Move(ref query, in options, request.Delta.Z);
    }

    /// <summary>The request's move, and what it met.</summary>
    private ResolveResult Reported(ref Neighbourhood lands, in MoveRequest request, out MoveReport report)
    {
        MovementOptions options = request.Options;
        var query = new MoveQuery(ref lands, request.Position, request.CellId, new Vector2(request.Delta.X, request.Delta.Y), request.StepUpHeight, in options);
        lands.Reporting = true;
        ResolveResult result = Move(ref query, in options, request.Delta.Z);
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
