using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics;

// The one preamble of every query that meets the movers: checked, its neighbourhood made, the movers near its start met
// and held when there are any, its own part run, and the hold let go whatever happens.
public sealed partial class PhysicsEngine
{
    /// <summary>
    /// A query's own part, run by <see cref="Query{TBody, TResult}"/>: a struct (a ref struct when it holds references to
    /// the caller's arguments), so each query's preamble is compiled for it with no call through the interface.
    /// </summary>
    private interface IQueryBody<TResult> : IHeldBody<TResult>
    {
        /// <summary>Checks the arguments: an <see cref="ArgumentException"/> naming the one that is wrong.</summary>
        void Validate();

        /// <summary>Reads what the query reads before the movers are met (the request's commit number); most read nothing.</summary>
        void Begin(PhysicsEngine engine);

        /// <summary>Meets the movers near the query's start in <paramref name="lands"/> (<see cref="Neighbourhood.Meet"/> or <see cref="Neighbourhood.MeetAlong"/>): whether it holds them.</summary>
        bool Meet(ref Neighbourhood lands, MoverRegistry movers, in WorldFrame frame);

    }

    /// <summary>A query's part run with movers held (<see cref="Held{TBody, TResult}"/>): the calls that write the preamble out use only this.</summary>
    private interface IHeldBody<TResult>
    {
        /// <summary>The query itself, in <paramref name="lands"/>; <paramref name="held"/>: with movers held.</summary>
        TResult Run(PhysicsEngine engine, ref Neighbourhood lands, bool held);
    }

    /// <summary>
    /// Every query that meets the movers: <paramref name="body"/> checked, its neighbourhood made, the movers near met and,
    /// when some are held, its part run out of line (<see cref="Held{TBody, TResult}"/>) with the hold let go whatever
    /// happens; else its part run here, with no handler to set up.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private TResult Query<TBody, TResult>(TBody body)
        where TBody : IQueryBody<TResult>, allows ref struct
    {
        body.Validate();
        body.Begin(this);
        var lands = new Neighbourhood(_registry);
        return _movers.Any && body.Meet(ref lands, _movers, in _frame)
            ? Held<TBody, TResult>(ref lands, in body)
            : body.Run(this, ref lands, held: false);
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
