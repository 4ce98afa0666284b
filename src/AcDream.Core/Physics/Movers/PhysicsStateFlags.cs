namespace AcDream.Core.Physics;

/// <summary>
/// The game's physics-state bits that decide whether a mover is met (the values of the game's <c>PhysicsState</c>, so a
/// caller maps them 1:1; the engine reads only these two).
/// </summary>
[Flags]
public enum PhysicsStateFlags : uint
{
    /// <summary>Solid.</summary>
    None = 0,

    /// <summary>0x4: does not block; a move that touches it records the touch (a portal's swirl, an open door).</summary>
    Ethereal = 0x4,

    /// <summary>0x10: with <see cref="Ethereal"/>, not met at all (not even recorded as touched).</summary>
    IgnoreCollisions = 0x10,
}
