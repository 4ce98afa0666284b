using System.Numerics;

namespace AcDream.Core.Physics;

/// <summary>
/// Outcome of <see cref="PhysicsEngine.Resolve(Vector3, uint, Vector3, float)"/>.
/// </summary>
/// <param name="Position">Resolved position in the engine's world frame, metres. Never NaN.</param>
/// <param name="CellId">Full cell id (<c>0xXXYYCCCC</c>) the mover ends up in: outdoor 0x0001..0x0040 or indoor 0x0100..0xFFFD.</param>
/// <param name="IsOnGround">
/// True exactly when <see cref="Position"/> stands on terrain or a floor: its Z within
/// <see cref="PhysicsConstants.GroundTolerance"/> (0.2 mm) of the terrain, or of the floor of
/// <see cref="CellId"/> nearest it, under its XY. False when the mover is above the ground (nothing
/// under it, a refused move in mid-air, or airborne with step down): the caller's gravity should act.
/// The one exception is a mover held because its landblock is not loaded: true, so it does not fall.
/// </param>
public readonly record struct ResolveResult(
    Vector3 Position,
    uint CellId,
    bool IsOnGround);
