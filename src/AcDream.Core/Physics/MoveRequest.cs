using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// One move asked of the engine (<see cref="PhysicsEngine.Resolve(in MoveRequest, Span{uint})"/>): where the mover
/// stands, the move, the step it may climb, and, beside them, what the spec's four arguments do not say.
/// </summary>
/// <remarks>
/// Built as <c>new MoveRequest(position, cellId, delta, stepUpHeight) { Options = MovementOptions.Player, MoverId = id }</c>.
/// With the defaults (no options, no mover, no report) the answer is bit for bit that of the spec's four-argument
/// <see cref="PhysicsEngine.Resolve(Vector3, uint, Vector3, float)"/>.
/// </remarks>
/// <param name="Position">Where the mover's feet are, world metres.</param>
/// <param name="CellId">The cell the mover is in (<c>0xXXYYCCCC</c>); outdoors any outdoor number, 0 included, is recomputed from the position.</param>
/// <param name="Delta">The intended move, world metres; its Z is ignored unless <see cref="MovementOptions.Vertical"/> (with a body) moves the body up and down by it.</param>
/// <param name="StepUpHeight">Highest rise one move (one sub-step when sweeping) may climb, metres, ≥ 0.</param>
public readonly record struct MoveRequest(Vector3 Position, uint CellId, Vector3 Delta, float StepUpHeight)
{
    /// <summary>The opt-in effects to simulate (<see cref="MovementOptions"/>); default: none, the spec's engine.</summary>
    public MovementOptions Options { get; init; }

    /// <summary>
    /// The id the mover is registered under in <see cref="PhysicsEngine.Movers"/>: its own walls are then not met, and
    /// the rules of who blocks whom read its state. 0 (the default): not a registered mover.
    /// </summary>
    public uint MoverId { get; init; }

    /// <summary>Whether the result names the floor the answer stands on and the wall it met (<see cref="MoveResult.Report"/>); off by default, as it costs a look at the ground under the answer.</summary>
    public bool WithReport { get; init; }
}
