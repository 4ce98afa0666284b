using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// What one <c>Resolve</c> met: the floor its answer stands on and the wall that stopped or slid it.
/// Filled by <see cref="PhysicsEngine.Resolve(in MoveRequest, Span{uint})"/> when <see cref="MoveRequest.WithReport"/> asks.
/// </summary>
/// <param name="Floor">
/// The ground under the answer when <see cref="ResolveResult.IsOnGround"/> is true: the terrain, the cell's
/// floor or an object's floor the position stands on, with its normal; <see cref="SurfaceKind.None"/> when
/// airborne or held (the land is not loaded).
/// </param>
/// <param name="Wall">
/// When the answer's outcome is <see cref="ResolveOutcome.Wall"/>, <see cref="ResolveOutcome.OuterWall"/> or
/// <see cref="ResolveOutcome.Slid"/> along a wall: the wall, shell or cylinder that stopped or slid the
/// mover, with the answer's <see cref="ResolveResult.SurfaceNormal"/> (zero for a building's outer wall found
/// by the doors-only rule, as there); <see cref="SurfaceKind.None"/> for every other outcome and for a call's
/// limit of cell visits.
/// </param>
public readonly record struct MoveReport(SurfaceContact Floor, SurfaceContact Wall);
