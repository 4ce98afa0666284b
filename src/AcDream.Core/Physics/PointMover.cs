using System.Numerics;
using System.Runtime.CompilerServices;

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
        if (q.Options.SweepStepLength is float sweep && q.Delta.LengthSquared() > sweep * sweep)
        {
            return Sweep(ref q, sweep);
        }

        return Step(ref q);
    }

    /// <summary>Equal sub-steps no longer than <paramref name="sweep"/>, stopping at the first refused one, whose outcome the answer reports.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: its queries would be zeroed on every call, swept or not
    private ResolveResult Sweep(ref MoveQuery q, float sweep)
    {
        int steps = SubSteps(q.Delta, sweep);
        Vector2 step = q.Delta / steps;
        MoveQuery query = q.Next(q.Position, q.CellId, step);
        ResolveResult result = Step(ref query);
        for (int i = 1; i < steps && !result.IsRefused; i++)
        {
            query = q.Next(result.Position, result.CellId, step);
            result = Answers.Continue(result, Step(ref query));
        }

        return result;
    }

    /// <summary>How many equal sub-steps no longer than <paramref name="sweep"/> a move of <paramref name="move"/> takes (at most <see cref="PhysicsConstants.MaxSweepSteps"/>).</summary>
    public static int SubSteps(Vector2 move, float sweep) =>
        (int)Math.Min(Math.Ceiling(move.Length() / (double)sweep), PhysicsConstants.MaxSweepSteps);

    /// <summary>One move, end-point checked.</summary>
    public ResolveResult Step(ref MoveQuery query) =>
        CellIds.IsIndoor(query.CellId) ? indoor.Resolve(ref query) : outdoor.Resolve(ref query);
}
