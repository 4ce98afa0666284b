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
    public ResolveResult Move(Vector3 pos, uint cellId, Vector2 move, float stepUp, in MovementOptions options)
    {
        if (options.SweepStepLength is float sweep && move.LengthSquared() > sweep * sweep)
        {
            return Sweep(pos, cellId, move, stepUp, in options, sweep);
        }

        var query = new MoveQuery(pos, cellId, move, stepUp, in options);
        return Step(ref query);
    }

    /// <summary>Equal sub-steps no longer than <paramref name="sweep"/>, stopping at the first refused one, whose outcome the answer reports.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of Resolve: its queries would be zeroed on every call, swept or not
    private ResolveResult Sweep(Vector3 pos, uint cellId, Vector2 move, float stepUp, in MovementOptions options, float sweep)
    {
        int steps = (int)Math.Min(Math.Ceiling(move.Length() / (double)sweep), PhysicsConstants.MaxSweepSteps);
        Vector2 step = move / steps;
        var query = new MoveQuery(pos, cellId, step, stepUp, in options);
        ResolveResult result = Step(ref query);
        for (int i = 1; i < steps && !result.IsRefused; i++)
        {
            query = new MoveQuery(result.Position, result.CellId, step, stepUp, in options);
            ResolveResult next = Step(ref query);
            result = next.IsRefused ? result with { Outcome = next.Outcome, SurfaceNormal = next.SurfaceNormal } : next;
        }

        return result;
    }

    /// <summary>One move, end-point checked.</summary>
    public ResolveResult Step(ref MoveQuery query) =>
        CellIds.IsIndoor(query.CellId) ? indoor.Resolve(ref query) : outdoor.Resolve(ref query);
}
