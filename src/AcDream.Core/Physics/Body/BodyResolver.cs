using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Drawing;

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
    /// The body's move <paramref name="q"/>: its path among the walls (<see cref="BodyPlanner"/>), walked leg
    /// by leg as point moves, so floors, cells, steps and doorways are decided as for a point. A path with no
    /// contact is the point move itself (swept, its sub-steps aimed as a leg's: see <see cref="Leg"/>).
    /// With walkable slope, a leg refused as too steep slides along the slope's contour once
    /// (<paramref name="contourLeft"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve, so a call without a body pays nothing for it
    [SkipLocalsInit] // the path's points are written before they are read
    public ResolveResult Resolve(ref MoveQuery q, bool contourLeft)
    {
        Span<Vector2> points = stackalloc Vector2[PhysicsConstants.MaxBodyContacts + 2];
        var path = default(BodyPath);
        int lbX = 0, lbY = 0;
        bool planned = q.Delta != Vector2.Zero && planner.Plan(ref q, q.Options.Body!.Value, points, ref path, out lbX, out lbY);
        var start = new ResolveResult(q.Position, q.CellId, false);
        if (!planned || path.Contacts == 0)
        {
            // Free: the point move itself; a swept one aims each sub-step at its point of the path (see Leg), and
            // checks the ceiling after each of its sub-steps, from where that sub-step set out.
            bool swept = planned && q.Options.SweepStepLength is float sweep && q.Delta.LengthSquared() > sweep * sweep;
            ResolveResult free = swept ? Leg(ref q, start, points[0], points[1], frame.Origin(lbX, lbY)) : point.Move(ref q);
            // Not planned for a real move: no land under the mover, so no ceiling to check at the end.
            if (!free.IsRefused && !swept && (planned || q.Delta == Vector2.Zero) && LowCeiling(ref q, q.Position, in free, out Vector3 ceiling))
            {
                return Stopped(ref q, ceiling);
            }

            return contourLeft && free.Outcome == ResolveOutcome.SlopeTooSteep && q.Options.WalkableSlope
                ? AlongContour(ref q, free)
                : free;
        }

        var wall = new Vector3(path.Normal.X, path.Normal.Y, 0f);
        q.Meet(path.Wall.Kind, path.Wall.Id);
        if (MoveDrawing.On)
        {
            MoveDrawing.BodyContact(frame.ToWorld(lbX, lbY, points[path.Count > 1 ? 1 : 0], q.Z), path.Normal, q.Options.Body!.Value);
        }

        if (path.Count == 1)
        {
            return Stopped(ref q, wall);
        }

        ResolveResult result = start;
        Vector2 origin = frame.Origin(lbX, lbY);
        for (int i = 1; i < path.Count; i++)
        {
            ResolveResult next = Leg(ref q, result, points[i - 1], points[i], origin);
            if (next.IsRefused)
            {
                if (contourLeft && next.Outcome == ResolveOutcome.SlopeTooSteep && q.Options.WalkableSlope)
                {
                    MoveQuery along = q.Next(result.Position, result.CellId, points[i] - (new Vector2(result.Position.X, result.Position.Y) - origin));
                    return AlongContour(ref along, next);
                }

                return i == 1 ? next : Answers.Continue(result, next);
            }

            result = next;
        }

        if (result.Outcome != ResolveOutcome.Moved)
        {
            return result;
        }

        q.Meet(path.Wall.Kind, path.Wall.Id); // the path's wall, over what its legs met

        // A path whose corners the world frame rounds back onto the start (a body at rest against a corner,
        // far from the origin) did not slide: it is stopped.
        bool stayed = result.Position.X == q.Position.X && result.Position.Y == q.Position.Y;
        return result with { Outcome = stayed ? ResolveOutcome.Wall : ResolveOutcome.Slid, SurfaceNormal = wall };
    }

    /// <summary>
    /// One leg of a body's path, <paramref name="from"/> → <paramref name="to"/> (landblock-local to
    /// <paramref name="origin"/>), as a point move from <paramref name="at"/> (its position and cell): in
    /// equal sub-steps when <see cref="MovementOptions.SweepStepLength"/> asks, stopping at the first refused
    /// one as <see cref="PointMover"/>'s sweep does. Each sub-step aims at its point of the leg from wherever
    /// the last answer was rounded to, so the world frame's rounding of one sub-step or corner is not carried
    /// into the next: it piled up past the body's skin at the far corner of the global frame (a 2 m slide in
    /// five sub-steps ended 3.7 mm into the wall; 5 m moves ended centimetres off their paths).
    /// </summary>
    private ResolveResult Leg(ref MoveQuery q, ResolveResult at, Vector2 from, Vector2 to, Vector2 origin)
    {
        Vector2 leg = to - from;
        int steps = q.Options.SweepStepLength is float sweep && leg.LengthSquared() > sweep * sweep ? PointMover.SubSteps(leg, sweep) : 1;
        ResolveResult result = default;
        for (int k = 1; k <= steps; k++)
        {
            Vector2 target = k == steps ? to : from + (leg * ((float)k / steps));
            MoveQuery query = q.Next(at.Position, at.CellId, target - (new Vector2(at.Position.X, at.Position.Y) - origin));
            ResolveResult next = q.Options.SweepStepLength is null ? point.Step(ref query) : point.SweptStep(ref query);
            if (next.IsRefused)
            {
                return k == 1 ? next : Answers.Continue(result, next);
            }

            if (LowCeiling(ref q, at.Position, in next, out Vector3 ceiling))
            {
                if (k > 1)
                {
                    return result with { Outcome = ResolveOutcome.Wall, SurfaceNormal = ceiling };
                }

                MoveQuery stay = q.Next(at.Position, at.CellId, q.Delta);
                return Stopped(ref stay, ceiling);
            }

            MoveDrawing.SubStep(at.Position, next.Position);
            (result, at) = (next, next);
        }

        return result;
    }

    /// <summary>
    /// Whether a body that has stepped up from <paramref name="from"/> to <paramref name="next"/> (its feet above
    /// those of the move <paramref name="q"/>, where its path was planned) met a wall or ceiling of its new height
    /// band on the way (<see cref="BodyPlanner.MetInNewBand"/>): a doorway lower than the body above the floor it
    /// would stand on stops it, where the band of the feet it set out with let it under the lintel (the player,
    /// 1.835 m tall, stepped up into the cottage's 1.8 m door cells and stood there with its head in the wall).
    /// A body already overlapping a wall may step up along or away from it. Lifted in place (no move), any
    /// overlap of the new band stops it. <paramref name="normal"/>: the wall's, seen from above.
    /// </summary>
    private bool LowCeiling(ref MoveQuery q, Vector3 from, in ResolveResult next, out Vector3 normal)
    {
        normal = default;
        if (!(next.Position.Z > q.Z + PhysicsConstants.GroundTolerance))
        {
            return false;
        }

        Vector2 outward;
        bool moved = next.Position.X != from.X || next.Position.Y != from.Y;
        if (!(moved
            ? planner.MetInNewBand(ref q, from, next.Position, next.CellId, out outward)
            : planner.Overlap(ref q, next.Position, next.CellId, q.Options.Body!.Value, out outward) > 0f))
        {
            return false;
        }

        normal = new Vector3(outward.X, outward.Y, 0f);
        return true;
    }

    /// <summary>A body stopped where it is (the start of <paramref name="q"/>) by a wall of normal <paramref name="wall"/>: <see cref="Stay"/>, reported as a wall.</summary>
    private ResolveResult Stopped(ref MoveQuery q, Vector3 wall)
    {
        ResolveResult stay = Stay(ref q);
        return stay.Outcome == ResolveOutcome.Moved ? stay with { Outcome = ResolveOutcome.Wall, SurfaceNormal = wall } : stay;
    }

    /// <summary>
    /// Walkable slope with a body: <paramref name="refused"/> was too steep to climb; the move goes on
    /// with its uphill part taken out (along the slope's contour), or the refusal stands.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: rare, and only with a body
    public ResolveResult AlongContour(ref MoveQuery q, ResolveResult refused)
    {
        var downhill = new Vector2(refused.SurfaceNormal.X, refused.SurfaceNormal.Y);
        float length = downhill.Length();
        if (length == 0f)
        {
            return refused;
        }

        downhill /= length;
        float uphill = -Vector2.Dot(q.Delta, downhill);
        Vector2 contour = uphill > 0f ? q.Delta + (downhill * uphill) : q.Delta;
        if (contour.LengthSquared() < PhysicsConstants.ContactTolerance * PhysicsConstants.ContactTolerance)
        {
            return refused;
        }

        MoveQuery along = q.Next(q.Position, q.CellId, contour);
        ResolveResult result = planner.IsOpenGround(ref along, contour, q.Options.Body!.Value)
            ? point.Move(ref along)
            : Resolve(ref along, contourLeft: false);
        return result.IsRefused
            ? refused
            : result with { Outcome = ResolveOutcome.Slid, SurfaceNormal = refused.SurfaceNormal };
    }

    /// <summary>
    /// A body stopped at once by a wall stays where it is (the start of <paramref name="q"/>): the answer of
    /// not moving, with the refusal ground rule (<see cref="Answers.Refuse"/>): without step down, feet more
    /// than the ground tolerance above the ground stay in the air.
    /// </summary>
    private ResolveResult Stay(ref MoveQuery q)
    {
        MoveQuery still = q.Next(q.Position, q.CellId, Vector2.Zero);
        ResolveResult stay = point.Move(ref still);
        return q.Options.StepDownHeight is null && stay.IsOnGround && stay.Outcome == ResolveOutcome.Moved
            && q.Z - stay.Position.Z > PhysicsConstants.GroundTolerance
            ? stay with { Position = stay.Position with { Z = q.Z }, IsOnGround = false }
            : stay;
    }
}
