using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Outcome of <see cref="PhysicsEngine.Resolve(Vector3, uint, Vector3, float)"/>.
/// </summary>
/// <param name="Position">Resolved position in the engine's world frame, metres. Never NaN.</param>
/// <param name="CellId">Full cell id (<c>0xXXYYCCCC</c>) the mover ends up in: outdoor 0x0001..0x0040 or indoor 0x0100..0xFFFD.</param>
/// <param name="IsOnGround">True when <see cref="Position"/> stands on terrain or a floor; false when nothing is under the mover and the caller's gravity should act.</param>
public readonly record struct ResolveResult(
    Vector3 Position,
    uint CellId,
    bool IsOnGround);
