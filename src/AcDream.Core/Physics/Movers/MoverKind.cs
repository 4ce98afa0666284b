namespace AcDream.Core.Physics;

/// <summary>What a mover is, for the rules of who collides with whom.</summary>
public enum MoverKind : byte
{
    /// <summary>Any other thing (a cart, a chest).</summary>
    Object = 0,

    /// <summary>A creature; a player is a creature with <see cref="ObjectDescriptionFlags.Player"/>.</summary>
    Creature,

    /// <summary>A door: <see cref="MoverRegistry.Open"/> and <see cref="MoverRegistry.Close"/> apply (the door hold).</summary>
    Door,
}
