using System.Numerics;
using System.Runtime.CompilerServices;

namespace AcDream.Core.Physics;

/// <summary>
/// The body effect's move: the path <see cref="BodyPlanner"/> plans among the walls, walked leg by
/// leg as point moves (<see cref="PointMover"/>), so floors, cells, steps and doorways are decided as
/// for a point; the step-up ceiling check, the stop at a wall and the slide along a too-steep slope's
/// contour.
/// </summary>
internal sealed class BodyResolver(BodyPlanner planner, WorldFrame frame, PointMover point)
{
    /// <summary>
    /// The body's move: its path among the walls (<see cref="BodyPlanner"/>), walked leg by leg as
    /// point moves, so floors, cells, steps and doorways are decided as for a point. A path with no
    /// contact is the point move itself (swept, its sub-steps aimed as a leg's: see <see cref="Leg"/>).
    /// With walkable slope, a leg refused as too steep slides along the slope's contour once
    /// (<paramref name="contourLeft"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve, so a call without a body pays nothing for it
    [SkipLocalsInit] // the path's points are written before they are read
    public ResolveResult Resolve(Vector3 pos, uint cellId, Vector2 move, float stepUp, in MovementOptions options, bool contourLeft)
    {
        Span<Vector2> points = stackalloc Vector2[PhysicsConstants.MaxBodyContacts + 2];
        var path = default(BodySweep.Path);
        int lbX = 0, lbY = 0;
        bool planned = move != Vector2.Zero && planner.Plan(pos, cellId, move, stepUp, options.Body!.Value, points, ref path, out lbX, out lbY);
        if (!planned || path.Contacts == 0)
        {
            // Free: the point move itself; a swept one aims each sub-step at its point of the path (see Leg).
            ResolveResult free = planned && options.SweepStepLength is float sweep && move.LengthSquared() > sweep * sweep
                ? Leg(pos, cellId, points[0], points[1], frame.Origin(lbX, lbY), pos.Z, stepUp, in options)
                : point.Move(pos, cellId, move, stepUp, in options);
            // Not planned for a real move: no land under the mover, so no ceiling to check at the end.
            if (!free.IsRefused && (planned || move == Vector2.Zero) && LowCeiling(in free, pos.Z, stepUp, in options, out Vector3 ceiling))
            {
                return Stopped(pos, cellId, stepUp, in options, ceiling);
            }

            return contourLeft && free.Outcome == ResolveOutcome.SlopeTooSteep && options.WalkableSlope
                ? AlongContour(pos, cellId, move, stepUp, in options, free)
                : free;
        }

        var wall = new Vector3(path.Normal.X, path.Normal.Y, 0f);
        if (path.Count == 1)
        {
            return Stopped(pos, cellId, stepUp, in options, wall);
        }

        ResolveResult result = default;
        Vector3 at = pos;
        uint cell = cellId;
        Vector2 origin = frame.Origin(lbX, lbY);
        for (int i = 1; i < path.Count; i++)
        {
            ResolveResult next = Leg(at, cell, points[i - 1], points[i], origin, pos.Z, stepUp, in options);
            if (next.IsRefused)
            {
                if (contourLeft && next.Outcome == ResolveOutcome.SlopeTooSteep && options.WalkableSlope)
                {
                    return AlongContour(at, cell, points[i] - (new Vector2(at.X, at.Y) - origin), stepUp, in options, next);
                }

                return i == 1 ? next : result with { Outcome = next.Outcome, SurfaceNormal = next.SurfaceNormal };
            }

            (result, at, cell) = (next, next.Position, next.CellId);
        }

        if (result.Outcome != ResolveOutcome.Moved)
        {
            return result;
        }

        // A path whose corners the world frame rounds back onto the start (a body at rest against a corner,
        // far from the origin) did not slide: it is stopped.
        bool stayed = result.Position.X == pos.X && result.Position.Y == pos.Y;
        return result with { Outcome = stayed ? ResolveOutcome.Wall : ResolveOutcome.Slid, SurfaceNormal = wall };
    }

    /// <summary>
    /// One leg of a body's path, <paramref name="from"/> → <paramref name="to"/> (landblock-local to
    /// <paramref name="origin"/>), as a point move: in equal sub-steps when
    /// <see cref="MovementOptions.SweepStepLength"/> asks, stopping at the first refused one as
    /// <see cref="PointMover"/>'s sweep does. Each sub-step aims at its point of the leg from wherever the last answer
    /// was rounded to, so the world frame's rounding of one sub-step or corner is not carried into the
    /// next: it piled up past the body's skin at the far corner of the global frame (a 2 m slide in five
    /// sub-steps ended 3.7 mm into the wall; 5 m moves ended centimetres off their paths).
    /// </summary>
    private ResolveResult Leg(Vector3 at, uint cell, Vector2 from, Vector2 to, Vector2 origin, float planZ, float stepUp, in MovementOptions options)
    {
        Vector2 leg = to - from;
        int steps = options.SweepStepLength is float sweep && leg.LengthSquared() > sweep * sweep
            ? (int)Math.Min(Math.Ceiling(leg.Length() / (double)sweep), PhysicsConstants.MaxSweepSteps)
            : 1;
        ResolveResult result = default;
        for (int k = 1; k <= steps; k++)
        {
            Vector2 target = k == steps ? to : from + (leg * ((float)k / steps));
            var query = new MoveQuery(at, cell, target - (new Vector2(at.X, at.Y) - origin), stepUp, in options);
            ResolveResult next = point.Step(ref query);
            if (next.IsRefused)
            {
                return k == 1 ? next : result with { Outcome = next.Outcome, SurfaceNormal = next.SurfaceNormal };
            }

            if (LowCeiling(in next, planZ, stepUp, in options, out Vector3 ceiling))
            {
                return k == 1 ? Stopped(at, cell, stepUp, in options, ceiling) : result with { Outcome = ResolveOutcome.Wall, SurfaceNormal = ceiling };
            }

            (result, at, cell) = (next, next.Position, next.CellId);
        }

        return result;
    }

    /// <summary>
    /// Whether a body that has stepped up to <paramref name="next"/> (its feet above
    /// <paramref name="planZ"/>, where its path was planned) meets a wall or ceiling in its height band
    /// there: a doorway lower than the body above the floor it would stand on stops it, where the band of
    /// the feet it set out with let it under the lintel (the player, 1.835 m tall, stepped up into the
    /// cottage's 1.8 m door cells and stood there with its head in the wall). <paramref name="normal"/>:
    /// out of the deepest such wall, seen from above.
    /// </summary>
    private bool LowCeiling(in ResolveResult next, float planZ, float stepUp, in MovementOptions options, out Vector3 normal)
    {
        normal = default;
        if (!(next.Position.Z > planZ + PhysicsConstants.GroundTolerance)
            || !(planner.Overlap(next.Position, next.CellId, stepUp, options.Body!.Value, out Vector2 outward) > 0f))
        {
            return false;
        }

        normal = new Vector3(outward.X, outward.Y, 0f);
        return true;
    }

    /// <summary>A body stopped where it is by a wall of normal <paramref name="wall"/>: <see cref="Stay"/>, reported as a wall.</summary>
    private ResolveResult Stopped(Vector3 pos, uint cellId, float stepUp, in MovementOptions options, Vector3 wall)
    {
        ResolveResult stay = Stay(pos, cellId, stepUp, in options);
        return stay.Outcome == ResolveOutcome.Moved ? stay with { Outcome = ResolveOutcome.Wall, SurfaceNormal = wall } : stay;
    }

    /// <summary>
    /// Walkable slope with a body: <paramref name="refused"/> was too steep to climb; the move goes on
    /// with its uphill part taken out (along the slope's contour), or the refusal stands.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: rare, and only with a body
    public ResolveResult AlongContour(Vector3 pos, uint cellId, Vector2 move, float stepUp, in MovementOptions options, ResolveResult refused)
    {
        var downhill = new Vector2(refused.SurfaceNormal.X, refused.SurfaceNormal.Y);
        float length = downhill.Length();
        if (length == 0f)
        {
            return refused;
        }

        downhill /= length;
        float uphill = -Vector2.Dot(move, downhill);
        Vector2 contour = uphill > 0f ? move + (downhill * uphill) : move;
        if (contour.LengthSquared() < PhysicsConstants.ContactTolerance * PhysicsConstants.ContactTolerance)
        {
            return refused;
        }

        ResolveResult along = planner.IsOpenGround(pos, cellId, contour, options.Body!.Value)
            ? point.Move(pos, cellId, contour, stepUp, in options)
            : Resolve(pos, cellId, contour, stepUp, in options, contourLeft: false);
        return along.IsRefused
            ? refused
            : along with { Outcome = ResolveOutcome.Slid, SurfaceNormal = refused.SurfaceNormal };
    }

    /// <summary>
    /// A body stopped at once by a wall stays where it is: the answer of not moving, with the refusal
    /// ground rule (<see cref="Answers.Refuse"/>): without step down, feet more than the ground tolerance
    /// above the ground stay in the air.
    /// </summary>
    private ResolveResult Stay(Vector3 pos, uint cellId, float stepUp, in MovementOptions options)
    {
        ResolveResult stay = point.Move(pos, cellId, Vector2.Zero, stepUp, in options);
        return options.StepDownHeight is null && stay.IsOnGround && stay.Outcome == ResolveOutcome.Moved
            && pos.Z - stay.Position.Z > PhysicsConstants.GroundTolerance
            ? stay with { Position = stay.Position with { Z = pos.Z }, IsOnGround = false }
            : stay;
    }
}
