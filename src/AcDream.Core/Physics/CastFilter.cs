namespace AcDream.Core.Physics;

/// <summary>What a cast (<see cref="PhysicsEngine.Cast"/>) passes through; flags may be combined.</summary>
[Flags]
public enum CastFilter : byte
{
    /// <summary>It stops at everything: terrain, cells, objects and every registered mover, Ethereal or not, except one both Ethereal and IgnoreCollisions, which nothing meets (a pointer's ray).</summary>
    None = 0,

    /// <summary>It passes creatures and players (a camera's).</summary>
    IgnoreCreatures = 1,

    /// <summary>It stops only at solid things: movers that are Ethereal (an open door, a spell's swirl) are passed.</summary>
    SolidOnly = 2,
}
