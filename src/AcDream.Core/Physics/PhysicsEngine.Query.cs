using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics;

// What every query that meets the movers shares: checked, its neighbourhood made, the movers near its start met (each
// call writes that out, measured: a generic form cost the literal call 5–15 %) and, when some are held, its own part run
// out of line with the hold let go whatever happens (Held).
public sealed partial class PhysicsEngine
{
    /// <summary>A query's own part, run with movers held by <see cref="Held{TBody, TResult}"/>: a struct, so each query's hold is compiled for it.</summary>
    private interface IHeldBody<TResult>
    {
        /// <summary>The query itself, in <paramref name="lands"/>; <paramref name="held"/>: with movers held.</summary>
        TResult Run(PhysicsEngine engine, ref Neighbourhood lands, bool held);
    }

    /// <summary>A query that holds movers: its part, and the hold let go whatever happens.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)] // kept out of the query: a call with no mover near has no handler to set up
    private TResult Held<TBody, TResult>(ref Neighbourhood lands, scoped in TBody body)
        where TBody : IHeldBody<TResult>, allows ref struct
    {
        try
        {
            return body.Run(this, ref lands, held: true);
        }
        finally
        {
            lands.Release();
        }
    }

    /// <summary>
    /// How far from its start a call's queries of the movers reach (metres, seen from above): its move (|x| + |y|, at least
    /// its length), with vertical motion also its |z| (a fall stopped by a steep face or a creature's top slides off
    /// sideways by at most half the fall it stopped), and its body's radius (every box a call asks about lies within
    /// them of its start: its path, the slides along it, the rise, the fall and the touches), and 5 cm for the skin, the
    /// contact tolerance and the world frame's rounding.
    /// </summary>
    private static float MoverReach(System.Numerics.Vector3 delta, in MovementOptions options) =>
        MathF.Abs(delta.X) + MathF.Abs(delta.Y) + (options.MovesVertically ? MathF.Abs(delta.Z) : 0f)
        + (options.Body is MoverBody body ? body.Radius : 0f) + 0.05f;
}
