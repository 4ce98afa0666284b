namespace AcDream.Core.Dat;

/// <summary>
/// A placed static object: a GfxObj (<c>0x01xxxxxx</c>) or Setup (<c>0x02xxxxxx</c>) at
/// <see cref="Frame"/> (object-local → landblock-local, metres), in a <see cref="LandBlockInfo"/>
/// (outdoors) or an <see cref="EnvCell"/>'s <see cref="EnvCell.StaticObjects"/> (inside that cell).
/// </summary>
public sealed class Stab
{
    /// <summary>The GfxObj or Setup id.</summary>
    public uint Id { get; set; }

    /// <summary>Object-local → landblock-local placement.</summary>
    public Frame Frame { get; set; } = new();
}
