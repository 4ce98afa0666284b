using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Drawing;

namespace AcDream.Core.Physics;

/// <summary>
/// A point mover's move: one end-point checked step (<see cref="OutdoorResolver"/> or
/// <see cref="IndoorResolver"/> by the mover's cell), or equal sub-steps when the caller sweeps.
/// </summary>
internal sealed class PointMover(OutdoorResolver outdoor, IndoorResolver indoor)
{
    /// <summary>A point's move: swept in sub-steps when <see cref="MovementOptions.SweepStepLength"/> asks, else one step.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // Resolve's own path: inlined there, so the call with no body is the code it was
    public ResolveResult Move(ref MoveQuery q)
    {
        if (q.Options.SweepStepLength is float sweep)
        {
            return q.Delta.LengthSquared() > sweep * sweep ? Sweep(ref q, sweep) : Checked(ref q, SweptStep(ref q));
        }

        return Checked(ref q, Step(ref q));
    }

    /// <summary>Equal sub-steps no longer than <paramref name="sweep"/>, stopping at the first refused one, whose outcome the answer reports.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: its queries would be zeroed on every call, swept or not
    private ResolveResult Sweep(ref MoveQuery q, float sweep)
    {
        int steps = SubSteps(q.Delta, sweep);
        Vector2 step = q.Delta / steps;
        MoveQuery query = q.Next(q.Position, q.CellId, step);
        ResolveResult result = Checked(ref query, SweptStep(ref query));
        MoveDrawing.SubStep(q.Position, result.Position);
        for (int i = 1; i < steps && !result.IsRefused; i++)
        {
            query = q.Next(result.Position, result.CellId, step);
            result = Answers.Continue(result, Checked(ref query, SweptStep(ref query)));
            MoveDrawing.SubStep(query.Position, result.Position);
        }

        return result;
    }

    /// <summary>How many equal sub-steps no longer than <paramref name="sweep"/> a move of <paramref name="move"/> takes (at most <see cref="PhysicsConstants.MaxSweepSteps"/>).</summary>
    public static int SubSteps(Vector2 move, float sweep) =>
        (int)Math.Min(Math.Ceiling(move.Length() / (double)sweep), PhysicsConstants.MaxSweepSteps);

    /// <summary>One move, end-point checked.</summary>
    public ResolveResult Step(ref MoveQuery query) =>
        CellIds.IsIndoor(query.CellId) ? indoor.Resolve(ref query) : outdoor.Resolve(ref query);

    /// <summary><paramref name="result"/>, the answer of <paramref name="q"/>'s step, checked against the movers the call holds (none: as it is).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public ResolveResult Checked(ref MoveQuery q, ResolveResult result) =>
        q.Lands.Movers is null || q.Options.Body is not null ? result : AmongMovers(ref q, result); // (a body meets them in its sweep)

    /// <summary>
    /// A point's move (a body's meets the movers in its sweep) that crosses a solid mover's walls at the feet plus the step
    /// (as an object's) or just over the feet (a mover lower than the step) is refused where it
    /// stands: the answer of a move of zero from its start, with <see cref="ResolveOutcome.Wall"/> and the wall's normal.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Step: only with movers committed
    private ResolveResult AmongMovers(ref MoveQuery q, ResolveResult result)
    {
        if (result.IsRefused || q.Entry is null)
        {
            return result;
        }

        MoverFrame movers = q.Lands.Movers!;
        var line = new StepLine(q.P0, q.P1, q.Z + q.StepUp);
        var feet = new StepLine(q.P0, q.P1, q.Z + PhysicsConstants.GroundTolerance); // (a mover lower than the step is met too)
        var hit = ObjectHit.Over(0f);
        uint met = 0;
        for (Neighbourhood.MoverCursor near = q.Lands.MoversNear(q.Entry.X, q.Entry.Y, new WallBox(line.Lo, line.Hi, feet.H, line.H)); near.MoveNext();)
        {
            CellWalls walls = movers.Walls[near.Current];
            if (q.Lands.Blocks(near.Current)
                && (line.Less(near.Offset).FirstCrossing(walls, ref hit) | feet.Less(near.Offset).FirstCrossing(walls, ref hit)))
            {
                met = movers.Ids[near.Current];
            }
        }

        if (met == 0)
        {
            return result;
        }

        q.Meet(SurfaceKind.Mover, met);
        MoveQuery stay = q.Next(q.Position, q.CellId, Vector2.Zero);
        ResolveResult still = CellIds.IsIndoor(stay.CellId) ? indoor.Resolve(ref stay) : outdoor.Resolve(ref stay);
        return still with { Outcome = ResolveOutcome.Wall, SurfaceNormal = hit.Normal };
    }

    /// <summary>
    /// One sub-step of a swept move (<see cref="MovementOptions.SweepStepLength"/>), end-point checked; refused as a
    /// step too high that an object's floor caused (<see cref="MoveQuery.ObjectStep"/>: a stair), it is tried again
    /// in halves (<see cref="Climb"/>), so a mover whose sub-step spans a tread and the rise beyond it takes the
    /// tread and stops at the rise, as the game's sphere steps up at each riser it meets. Terrain and cells' floors
    /// are not halved: a slope too steep stays too steep, however short the move.
    /// </summary>
    public ResolveResult SweptStep(ref MoveQuery query)
    {
        ResolveResult result = Step(ref query);
        return query.ObjectStep ? Climb(ref query, result, 1) : result;
    }

    /// <summary>
    /// A move refused as a step too high at an object's floor (<paramref name="refused"/>), made in two halves, each end-point checked
    /// (and halved again when refused so, down to 1/2^<see cref="PhysicsConstants.MaxClimbHalvings"/> of the move):
    /// as far as the halves go, with the refusal of the first that is refused.
    /// </summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Step: only on a refusal
    private ResolveResult Climb(ref MoveQuery q, ResolveResult refused, int depth)
    {
        if (depth > PhysicsConstants.MaxClimbHalvings)
        {
            return refused;
        }

        Vector2 half = q.Delta * 0.5f;
        MoveQuery first = q.Next(q.Position, q.CellId, half);
        ResolveResult near = Half(ref first, depth);
        if (near.IsRefused)
        {
            return near;
        }

        MoveQuery second = q.Next(near.Position, near.CellId, q.Delta - half);
        return Answers.Continue(near, Half(ref second, depth));
    }

    /// <summary>One half of a climb: end-point checked, halved again when refused as a step too high at an object's floor.</summary>
    private ResolveResult Half(ref MoveQuery q, int depth)
    {
        ResolveResult result = Step(ref q);
        return q.ObjectStep ? Climb(ref q, result, depth + 1) : result;
    }
}
