namespace AcDream.Core.Physics;

/// <summary>Where a door is in its opening and closing (<see cref="MoverRegistry.Open"/>, <see cref="MoverRegistry.Close"/>).</summary>
public enum DoorState : byte
{
    /// <summary>Solid: it blocks from both sides.</summary>
    Closed = 0,

    /// <summary>Ethereal: it blocks nothing; a move through it records the touch.</summary>
    Open,

    /// <summary>Told to close, not yet solid: Ethereal until the first <see cref="MoverRegistry.Commit"/> at which nothing overlaps it (until that commit even with nothing in it).</summary>
    Closing,
}
