using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.Core.Physics.Surfaces;
using AcDream.Core.Physics.World;
using AcDream.Core.Physics.Point;

namespace AcDream.Core.Physics;

// The spec's call's and the options call's own parts, and their held paths.
public sealed partial class PhysicsEngine
{
    /// <summary>
    /// The move of a checked call: a body's in three dimensions when an effect asks (<see cref="Body.BodyMotion"/>, with the
    /// delta's Z <paramref name="dz"/>), else across the ground (<see cref="Body.BodyMotion.Horizontal"/>).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private ResolveResult Move(ref MoveQuery query, in MovementOptions options, float dz) =>
        options.InThreeD ? _motion.Resolve(ref query, dz) : _motion.Horizontal(ref query);

    /// <summary>The literal call's held path, out of line so the call with no mover near keeps a small frame.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private ResolveResult HeldLiteral(ref Neighbourhood lands, Vector3 position, uint cellId, Vector3 delta, float stepUp) =>
        Held<Literal, ResolveResult>(ref lands, new Literal(position, cellId, delta, stepUp));

    /// <summary>The options call's held path, out of line as the literal one's.</summary>
    [MethodImpl(MethodImplOptions.NoInlining)]
    private ResolveResult HeldOptioned(ref Neighbourhood lands, in MoveRequest move)
    {
        MovementOptions options = move.Options;
        return Held<Optioned, ResolveResult>(ref lands, new Optioned(move.Position, move.CellId, move.Delta, move.StepUpHeight, in options));
    }

    /// <summary>The spec's call's part (<see cref="Resolve(Vector3, uint, Vector3, float)"/>): no effects, not a mover; checked again when movers are held.</summary>
    private readonly struct Literal(Vector3 position, uint cellId, Vector3 delta, float stepUp) : IHeldBody<ResolveResult>
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public ResolveResult Run(PhysicsEngine engine, ref Neighbourhood lands, bool held)
        {
            MovementOptions none = default; // no effects: the spec's engine
            var query = new MoveQuery(ref lands, position, cellId, new Vector2(delta.X, delta.Y), stepUp, in none);
            ResolveResult result = engine._point.Step(ref query);
            return held ? engine._point.Checked(ref query, result) : result;
        }
    }

    /// <summary>The held part of the call with options.</summary>
    private readonly ref struct Optioned : IHeldBody<ResolveResult>
    {
        private readonly ref readonly MovementOptions _options;
        private readonly Vector3 _position, _delta;
        private readonly uint _cellId;
        private readonly float _stepUp;

        public Optioned(Vector3 position, uint cellId, Vector3 delta, float stepUp, ref readonly MovementOptions options)
        {
            _options = ref options;
            (_position, _cellId, _delta, _stepUp) = (position, cellId, delta, stepUp);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public ResolveResult Run(PhysicsEngine engine, ref Neighbourhood lands, bool held)
        {
            var query = new MoveQuery(ref lands, _position, _cellId, new Vector2(_delta.X, _delta.Y), _stepUp, in _options);
            return engine.Move(ref query, in _options, _delta.Z);
        }
    }
}
