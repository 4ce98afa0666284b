using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Point;

namespace AcDream.Core.Physics;

// The two Resolve calls' own parts, run through the one preamble (Query).
public sealed partial class PhysicsEngine
{
    /// <summary>
    /// The move of a checked call: a body's in three dimensions when an effect asks (<see cref="Body.BodyMotion"/>, with the
    /// delta's Z <paramref name="dz"/>), else across the ground (<see cref="Body.BodyMotion.Horizontal"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private ResolveResult Move(ref MoveQuery query, in MovementOptions options, float dz) =>
        options.InThreeD ? _motion.Resolve(ref query, dz) : _motion.Horizontal(ref query);

    /// <summary>The spec's call (<see cref="Resolve(Vector3, uint, Vector3, float)"/>): no effects, not a mover; checked again when movers are held.</summary>
    /// <summary>The literal call's held path, out of line so the call with no mover near keeps a small frame.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private ResolveResult HeldLiteral(ref Neighbourhood lands, Vector3 position, uint cellId, Vector3 delta, float stepUp) =>
        Held<Literal, ResolveResult>(ref lands, new Literal(position, cellId, delta, stepUp));

    /// <summary>The options call's held path, out of line as the literal one's.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private ResolveResult HeldOptioned(ref Neighbourhood lands, in MoveRequest move)
    {
        MovementOptions options = move.Options;
        return Held<Optioned, ResolveResult>(ref lands, new Optioned(move.Position, move.CellId, move.Delta, move.StepUpHeight, in options, 0));
    }

    private readonly struct Literal(Vector3 position, uint cellId, Vector3 delta, float stepUp) : IQueryBody<ResolveResult>
    {
        public void Validate() => MoveQuery.Validate(position, cellId, delta, stepUp);

        public void Begin(PhysicsEngine engine)
        {
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool Meet(ref Neighbourhood lands, MoverRegistry movers, in WorldFrame frame) =>
            lands.Meet(movers, in frame, position, cellId, MathF.Abs(delta.X) + MathF.Abs(delta.Y) + 0.05f, 0); // (MoverReach with no effects)

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public ResolveResult Run(PhysicsEngine engine, ref Neighbourhood lands, bool held)
        {
            MovementOptions none = default; // no effects: the spec's engine
            var query = new MoveQuery(ref lands, position, cellId, new Vector2(delta.X, delta.Y), stepUp, in none);
            ResolveResult result = engine._point.Step(ref query);
            return held ? engine._point.Checked(ref query, result) : result;
        }
    }

    /// <summary>The call with options, as the mover <c>self</c> (0: none).</summary>
    private readonly ref struct Optioned : IQueryBody<ResolveResult>
    {
        private readonly ref readonly MovementOptions _options;
        private readonly Vector3 _position, _delta;
        private readonly uint _cellId, _self;
        private readonly float _stepUp;

        public Optioned(Vector3 position, uint cellId, Vector3 delta, float stepUp, ref readonly MovementOptions options, uint self)
        {
            _options = ref options;
            (_position, _cellId, _delta, _stepUp, _self) = (position, cellId, delta, stepUp, self);
        }

        public void Validate() => MoveQuery.Validate(_position, _cellId, _delta, _stepUp);

        public void Begin(PhysicsEngine engine)
        {
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool Meet(ref Neighbourhood lands, MoverRegistry movers, in WorldFrame frame) =>
            lands.Meet(movers, in frame, _position, _cellId, MoverReach(_delta, in _options), _self);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public ResolveResult Run(PhysicsEngine engine, ref Neighbourhood lands, bool held)
        {
            var query = new MoveQuery(ref lands, _position, _cellId, new Vector2(_delta.X, _delta.Y), _stepUp, in _options);
            return engine.Move(ref query, in _options, _delta.Z);
        }
    }
}
