namespace AcDream.Core.Physics;

/// <summary>
/// The game's object-description bits of players and creatures that the rules between two players read (the values of
/// the game's <c>ObjectDescriptionFlags</c>, so a caller maps them 1:1; the engine reads only these four).
/// </summary>
[Flags]
public enum ObjectDescriptionFlags : uint
{
    /// <summary>None of the four.</summary>
    None = 0,

    /// <summary>0x8: a player.</summary>
    Player = 0x8,

    /// <summary>0x20: a player-killer.</summary>
    PlayerKiller = 0x20,

    /// <summary>0x200000: impenetrable: another player does not pass through it, nor it through another.</summary>
    Impenetrable = 0x200000,

    /// <summary>0x2000000: a PK-lite player.</summary>
    PkLite = 0x2000000,
}
