using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Point;

namespace AcDream.Core.Physics.Body;

/// <summary>
/// A body's move in three dimensions (<see cref="MovementOptions.Vertical"/>, <see cref="MovementOptions.Footing"/>,
/// <see cref="MovementOptions.EdgeSlide"/>) on top of its move across the ground (<see cref="Horizontal"/>): through the
/// air, with its rise stopped under ceilings and its fall landed on the first floor; standing on floors under its
/// footprint; held at edges.
/// </summary>
internal sealed class BodyMotion(WorldFrame frame, PointMover point, BodyResolver body, BodyPlanner planner)
{
    /// <summary>Edge slide: how far inside the last point the floor holds it a body held at an edge stops, metres (1 mm, plus the world frame's rounding).</summary>
    private const float EdgeMargin = 0.001f;

    /// <summary>
    /// The move across the ground of a checked call: a body's among the walls near it, else the point's
    /// (<see cref="PointMover"/>); with walkable slope, a body refused by a slope slides along its contour.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public ResolveResult Horizontal(ref MoveQuery query)
    {
        if (query.Options.Body is MoverBody b && (query.Delta == Vector2.Zero || !planner.IsOpenGround(ref query, query.Delta, b)))
        {
            return body.Resolve(ref query, contourLeft: true);
        }

        // No body, or a body on open ground (no wall in its reach): the point move is the answer.
        ResolveResult result = point.Move(ref query);
        return result.Outcome == ResolveOutcome.SlopeTooSteep && query.Options.Body.HasValue && query.Options.WalkableSlope
            ? body.AlongContour(ref query, result)
            : result;
    }

    /// <summary>Tests' seam: a body's move always planned (<see cref="BodyResolver.Resolve"/>), never the open-ground shortcut.</summary>
    public ResolveResult Planned(ref MoveQuery query) => body.Resolve(ref query, contourLeft: true);

    /// <summary>
    /// The move <paramref name="q"/> of a body with an effect in three dimensions, <paramref name="dz"/> metres up (the
    /// delta's Z): through the air when it has vertical motion and rises, falls or does not stand at the start; else
    /// across the ground (<see cref="Walk"/>), held at an edge it would step off.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: a call without these effects pays nothing for it
    public ResolveResult Resolve(ref MoveQuery q, float dz)
    {
        bool vertical = q.Options.MovesVertically;
        if (vertical && (dz != 0f || !Stands(ref q)))
        {
            return Air(ref q, dz);
        }

        ResolveResult result = Walk(ref q);
        return q.Options.EdgeSlide && !result.IsOnGround && result.Outcome is ResolveOutcome.Moved or ResolveOutcome.Slid
            && q.Delta != Vector2.Zero && (vertical || Stands(ref q))
            ? AlongEdge(ref q, result)
            : result;
    }

    /// <summary>A move across the ground, standing where the body's footprint finds footing (<see cref="Foot"/>).</summary>
    private ResolveResult Walk(ref MoveQuery q) => Foot(ref q, Horizontal(ref q));

    /// <summary>
    /// A move through the air: in equal sub-steps no longer than the sweep (when the options sweep), each up then across,
    /// or across and down (never stepping down across, climbing at most <see cref="PhysicsConstants.AirStepUp"/>). A rise
    /// stops under the first surface over the body (<see cref="ResolveOutcome.Ceiling"/>); a fall lands on the first floor
    /// under it, and the rest of the move is walked on the ground; a face too steep to stand on (above
    /// <see cref="PhysicsConstants.LandingZ"/>) stops the fall and the body slides down it (<see cref="ResolveOutcome.Slid"/>
    /// with its normal).
    /// </summary>
    private ResolveResult Air(ref MoveQuery q, float dz)
    {
        float step = MathF.Min(q.StepUp, PhysicsConstants.AirStepUp);
        float length = MathF.Sqrt(q.Delta.LengthSquared() + (dz * dz));
        double wanted = q.Options.SweepStepLength is float sweep && length > sweep ? Math.Ceiling(length / (double)sweep) : 1d;
        int steps = (int)Math.Min(wanted, PhysicsConstants.MaxSweepSteps);

        // Each sub-step is one sweep: beyond the most sub-steps (each longer than the sweep) its move across is not cut
        // into sub-steps again, so a move through the air takes at most MaxSweepSteps sub-steps, not their square.
        MovementOptions options = wanted > PhysicsConstants.MaxSweepSteps ? q.Options with { SweepStepLength = float.MaxValue } : q.Options;
        MovementOptions air = options with { StepDownHeight = 0f };
        Vector2 across = q.Delta / steps;
        float up = dz / steps;
        var at = new ResolveResult(q.Position, q.CellId, false);
        (ResolveOutcome outcome, Vector3 normal) = (ResolveOutcome.Moved, default);
        bool landed = false;
        for (int k = 0; k < steps; k++)
        {
            Vector3 from = at.Position; // (where this sub-step sets out, for drawing)

            // Rising, the body first rises (its top stopped under the first surface over it), then moves across from there:
            // the move across is what resting there gives, its cell and ground found at its new height.
            if (up > 0f && !landed)
            {
                var rising = q.With(at.Position, at.CellId, Vector2.Zero, step, in air);
                float rise = planner.Rise(ref rising, at.Position, at.CellId, q.Options.Body!.Value, up, out Vector3 ceiling);
                at = at with { Position = at.Position with { Z = at.Position.Z + rise } };
                if (rise < up)
                {
                    (outcome, normal, up) = (ResolveOutcome.Ceiling, ceiling, 0f);
                }
            }

            // Falling, the move across steps down as far as this sub-step falls: it lands on the ground under its end
            // within that depth (or under its footprint), else it is that much lower, over the cell whose surface is below.
            // (Two ground tolerances more: lowered by the fall, feet that close to the ground would be standing on it.)
            MovementOptions fall = up < 0f && !landed ? options with { StepDownHeight = -up + (2f * PhysicsConstants.GroundTolerance) } : air;
            MoveQuery move = landed
                ? q.With(at.Position, at.CellId, across, q.StepUp, in options)
                : q.With(at.Position, at.CellId, across, step, in fall);
            float before = at.Position.Z;
            ResolveResult moved = Walk(ref move);
            if (moved.IsRefused || moved.Outcome == ResolveOutcome.Slid)
            {
                (outcome, normal) = outcome == ResolveOutcome.Ceiling ? (outcome, normal) : (moved.Outcome, moved.SurfaceNormal);
            }

            at = moved;
            MoveDrawing.SubStep(from, at.Position);
            if (landed || (at.IsOnGround && up == 0f))
            {
                landed |= at.IsOnGround;
                continue;
            }

            if (up < 0f && at.Outcome != ResolveOutcome.Held)
            {
                // A face too steep to stand on between where the feet were and where they land or fall to comes first.
                float depth = at.IsOnGround ? before - at.Position.Z : -up;
                Vector3 slope = default;
                float face = depth > 0f
                    ? planner.SteepUnder(ref move, at.Position with { Z = before }, at.CellId, q.Options.Body!.Value, depth, out slope)
                    : float.NaN;
                if (float.IsNaN(face) || (at.IsOnGround && !(face > at.Position.Z + PhysicsConstants.GroundTolerance)))
                {
                    (at, landed) = at.IsOnGround ? (at, true) : (at with { Position = at.Position with { Z = before + up } }, false);
                    continue;
                }

                // A face too steep to stand on stops the fall at its highest point under the body (in the air, not standing);
                // the part of the fall it stopped goes on along the face, down it: the body slides off.
                float stopped = face - (before + up);
                var downhill = new Vector2(slope.X, slope.Y) * (stopped * slope.Z);
                at = at with { Position = at.Position with { Z = face }, IsOnGround = false };
                (outcome, normal) = outcome == ResolveOutcome.Ceiling ? (outcome, normal) : (ResolveOutcome.Slid, slope);
                if (downhill != Vector2.Zero)
                {
                    MoveQuery off = q.With(at.Position, at.CellId, downhill, step, in air);
                    ResolveResult slid = Walk(ref off);
                    at = slid.IsRefused ? at : slid;
                }
            }
        }

        if (at.IsOnGround && at.Outcome != ResolveOutcome.Held)
        {
            // On the ground: at rest as a body standing there walks (its step, its footing), so that standing still there gives it again.
            MoveQuery rest = q.With(at.Position, at.CellId, Vector2.Zero, q.StepUp, in q.Options);
            at = Walk(ref rest);
        }

        return at with { Outcome = outcome, SurfaceNormal = normal };
    }

    /// <summary>
    /// Footing (<see cref="MovementOptions.Footing"/>): the answer <paramref name="result"/> of <paramref name="q"/> raised onto
    /// the highest floor under the body's footprint (within the support reach) that is higher than where it stands and no
    /// more than the step above the start's feet, or, when it is in the air, no more than its step down below it; and on
    /// from there to rest, as the point's ground is (a step from the floor it climbed), at most
    /// <see cref="PhysicsConstants.MaxClimbHalvings"/> times.
    /// </summary>
    private ResolveResult Foot(ref MoveQuery q, ResolveResult result)
    {
        bool indoor = CellIds.IsIndoor(result.CellId);
        if (!q.Options.Footing || result.Outcome == ResolveOutcome.Held
            || (q.Open && (indoor ? result.IsOnGround && result.CellId == q.CellId : !CellIds.IsIndoor(q.CellId))))
        {
            return result; // (nothing near the move where it stayed: the ground under the centre is all there is)
        }

        float reach = q.Options.Body!.Value.Radius * PhysicsConstants.SupportReach;
        float feet = q.Z;
        for (int i = 0; i < PhysicsConstants.MaxClimbHalvings; i++)
        {
            if (!Locator.TryFind(frame, ref q.Lands, result.Position, result.CellId, out Place place))
            {
                return result;
            }

            float z = result.Position.Z;
            if (result.IsOnGround && place.CellIndex >= 0 && place.Entry.Cells[place.CellIndex] is { Objects.Length: 0 } level
                && level.FloorLevel == z && (q.CellId == result.CellId || !CellIds.IsIndoor(q.CellId)))
            {
                return result; // on a cell whose floors are all at this height, with nothing standing in it: nothing higher holds it
            }

            float low = result.IsOnGround ? z + PhysicsConstants.GroundTolerance : z - (q.Options.StepDownHeight ?? 0f) - PhysicsConstants.GroundTolerance;
            int start = CellIds.IsIndoor(q.CellId) && CellIds.IsIndoor(result.CellId) && (q.CellId >> 16) == (result.CellId >> 16)
                && place.Entry.TryGetCellIndex(q.CellId, out int index) ? index : -1;

            // In the air, the floors of the other cells of its building too: a body over the edge of an opening or a doorway's
            // threshold is held by the floor beyond it, whichever cell its centre was found in.
            Support support = Supports.Highest(ref q.Lands, in place, start, new Footprint(place.Local, reach, low, MathF.Max(feet, z) + q.StepUp), !result.IsOnGround);
            if (!support.Found || (result.IsOnGround && !(support.Z > z)))
            {
                return result;
            }

            uint cellId = support.CellIndex >= 0 ? place.Entry.Cells[support.CellIndex].CellId : result.CellId;
            result = result with { Position = result.Position with { Z = support.Z }, CellId = cellId, IsOnGround = true };
            feet = support.Z;

            // On from there: the ground under the centre for feet at that height may be higher still, and so may a floor
            // within a step of it (the next tread).
            MoveQuery still = q.With(result.Position, result.CellId, Vector2.Zero, q.StepUp, in q.Options);
            ResolveResult settled = Horizontal(ref still);
            if (settled.IsOnGround && settled.Position.Z > support.Z)
            {
                (result, feet) = (settled with { Outcome = result.Outcome, SurfaceNormal = result.SurfaceNormal }, settled.Position.Z);
            }
        }

        return result;
    }

    /// <summary>
    /// Whether the body of <paramref name="q"/> stands at its start: its feet within the ground tolerance of the ground under
    /// its centre, or (footing) of a floor under its footprint; else, as the move itself finds the ground there (through
    /// its cell's portals), a body not moving and not stepping down is on the ground at its feet. A body whose
    /// landblock is not loaded is held: it stands.
    /// </summary>
    private bool Stands(ref MoveQuery q)
    {
        if (!Locator.TryFind(frame, ref q.Lands, q.Position, q.CellId, out Place place))
        {
            return true;
        }

        // The ground under the centre: the terrain or the cell's floor at the feet first (the common case, cheap), then
        // with the objects' floors.
        const float tolerance = PhysicsConstants.GroundTolerance;
        Vector2 p = place.Local;
        float z = place.CellIndex < 0
            ? place.Entry.Terrain.SampleZUnchecked(p.X, p.Y)
            : place.Entry.Cells[place.CellIndex].TrySampleFloor(p.X, p.Y, q.Z, out float floor) ? floor : float.NaN;
        if (MathF.Abs(z - q.Z) <= tolerance
            || (Ground.TryUnder(ref q.Lands, in place, q.Z, tolerance, out z, out _) && MathF.Abs(z - q.Z) <= tolerance))
        {
            return true;
        }

        if (q.Options.Footing
            && Supports.Highest(ref q.Lands, in place, -1, new Footprint(place.Local, q.Options.Body!.Value.Radius * PhysicsConstants.SupportReach, q.Z - tolerance, q.Z + tolerance)).Found)
        {
            return true;
        }

        MovementOptions still = q.Options with { StepDownHeight = 0f };
        MoveQuery stay = q.With(q.Position, q.CellId, Vector2.Zero, q.StepUp, in still);
        ResolveResult there = Walk(ref stay);
        return there.IsOnGround && MathF.Abs(there.Position.Z - q.Z) <= tolerance;
    }

    /// <summary>
    /// Edge slide: a body that stood at the start of <paramref name="q"/> and whose move <paramref name="off"/> left it in
    /// the air over a drop moves out to the edge of the floor it stood on (as far as the floor holds it) and on along the
    /// edge with the rest of its move (the edge's outward normal reported), or stays where it is
    /// (<see cref="ResolveOutcome.Edge"/>) when that gives no footing either.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // rare: only a move off an edge
    private ResolveResult AlongEdge(ref MoveQuery q, ResolveResult off)
    {
        if (!Locator.TryFind(frame, ref q.Lands, q.Position, q.CellId, out Place place)
            || !Locator.TryFind(frame, ref q.Lands, off.Position, off.CellId, out Place end)
            || !Ground.TryUnder(ref q.Lands, in end, off.Position.Z, 0f, out _, out _))
        {
            return off; // no ground at all under it (a cell with no floor there): no drop to be held from
        }

        // The end in the start's frame: the start's local point plus the move's rounded displacement.
        Vector2 to = place.Local + new Vector2(off.Position.X - q.Position.X, off.Position.Y - q.Position.Y);
        float reach = q.Options.Body!.Value.Radius * PhysicsConstants.SupportReach;
        (Vector2 outward, SurfaceContact edge, Vector2 nearest) = Supports.Edge(ref q.Lands, in place, place.Local, to, reach, q.Z);
        q.Meet(SurfaceKind.FloorEdge, edge.Id);
        if (MoveDrawing.On)
        {
            MoveDrawing.Edge(q.Position, place.Local, nearest, outward, edge.Id);
        }

        if (outward != Vector2.Zero)
        {
            // Out to where the floor still holds the body (its edge, plus the support reach with footing), less a margin;
            // the rest of the move along the edge.
            // The margin covers the world frame's rounding of where it stops (4 mm at the far corner of the global frame).
            float held = q.Options.Footing ? reach : 0f;
            float margin = EdgeMargin + (4f * Geometry.Spacing(MathF.Max(MathF.Abs(off.Position.X), MathF.Abs(off.Position.Y))));
            float past = Vector2.Dot(to - nearest, outward) - held + margin;
            Vector2 along = q.Delta - (outward * MathF.Max(past, 0f));
            if (along.LengthSquared() > PhysicsConstants.ContactTolerance * PhysicsConstants.ContactTolerance)
            {
                MoveQuery slide = q.Next(q.Position, q.CellId, along);
                ResolveResult slid = Walk(ref slide);
                if (slid.IsOnGround && !slid.IsRefused)
                {
                    return slid with { Outcome = ResolveOutcome.Slid, SurfaceNormal = new Vector3(outward, 0f) };
                }
            }
        }
        else if (to != place.Local)
        {
            outward = Vector2.Normalize(to - place.Local); // no floor's edge found (the terrain's ground): the move's own way
        }

        MoveQuery stay = q.Next(q.Position, q.CellId, Vector2.Zero);
        ResolveResult still = Walk(ref stay);
        return still with { Outcome = ResolveOutcome.Edge, SurfaceNormal = new Vector3(outward, 0f) };
    }
}
