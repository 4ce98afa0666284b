using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Point;
using AcDream.Core.Physics.Body;

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
    [MethodImpl(MethodImplOptions.NoInlining)] // the preamble compiled once here, not into each caller
#pragma warning disable RS0027 // (the spec's four-argument Resolve has no optional parameter to clash with; one general call reads best with the span optional)
    public MoveResult Resolve(in MoveRequest request, Span<uint> touched = default)
#pragma warning restore RS0027
        => _recorder is null ? Request(in request, touched) : Recorded(in request, touched);

    /// <summary>
    /// The general move: checked, the commit number read, its neighbourhood made and the movers near met; its part
    /// (<see cref="Requested"/>) run with them held when there are any (<see cref="Held{TBody, TResult}"/>), else here.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private MoveResult Request(in MoveRequest request, Span<uint> touched)
    {
        MoveQuery.Validate(in request);
        var body = new Requested(in request, touched, _movers.CommitNumber);
        var lands = new Neighbourhood(_registry);
        MovementOptions options = request.Options;
        return _movers.Any && lands.Meet(_movers, in _frame, request.Position, request.CellId, MoverReach(request.Delta, in options), request.MoverId)
            ? Held<Requested, MoveResult>(ref lands, in body)
            : body.Run(this, ref lands, held: false);
    }

    /// <summary>The general move with a recorder set, out of line as the cast's (<see cref="Recorded(in CastRequest)"/>).</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private MoveResult Recorded(in MoveRequest request, Span<uint> touched)
    {
        MoveResult result = Request(in request, touched);
        _recorder?.Resolved(in request, touched, in result);
        return result;
    }

    /// <summary>The general call's own part: its move, what it met when asked, and the movers it touched.</summary>
    private readonly ref struct Requested(ref readonly MoveRequest request, Span<uint> touched, long commit) : IHeldBody<MoveResult>
    {
        private readonly ref readonly MoveRequest _request = ref request;
        private readonly Span<uint> _touched = touched;
        private readonly long _commit = commit; // the commit read before the movers were met (none held: the answer read it)

        public MoveResult Run(PhysicsEngine engine, ref Neighbourhood lands, bool held)
        {
            ref readonly MoveRequest request = ref _request;
            if (!held)
            {
                return request.WithReport
                    ? new MoveResult(engine.Reported(ref lands, in request, out MoveReport report), report, 0, _commit)
                    : new MoveResult(engine.Moved(ref lands, in request), default, 0, _commit);
            }

            long commit = lands.Movers!.Commit;
            if (_touched.IsEmpty && !request.WithReport)
            {
                return new MoveResult(engine.Moved(ref lands, in request), default, 0, commit);
            }

            ResolveResult result = engine.Reported(ref lands, in request, out MoveReport met);
            int count = Touches.Along(engine._frame, ref lands, in request, in result, met.Wall.Kind == SurfaceKind.Mover ? met.Wall.Id : 0, _touched);
            return new MoveResult(result, request.WithReport ? met : default, count, commit);
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
                Support support = Supports.Highest(ref lands, in place, -1, new Footprint(place.Local, reach, result.Position.Z - tolerance, result.Position.Z + tolerance));
                floor = support.Found ? support.Floor : floor;
            }
        }

        return new MoveReport(floor, met);
    }
}
