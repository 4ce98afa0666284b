namespace AcDream.Core.Dat;

/// <summary>
/// A building of a landblock: its outer shell (<see cref="ModelId"/>, a GfxObj or Setup placed by
/// <see cref="Frame"/>, landblock-local metres) and the portals that lead from outdoors into its cells.
/// </summary>
public sealed class BuildingInfo
{
    /// <summary>The shell's GfxObj or Setup id.</summary>
    public uint ModelId { get; set; }

    /// <summary>Shell-local → landblock-local placement.</summary>
    public Frame Frame { get; set; } = new();

    /// <summary>Number of leaves of the building's drawing; not read by physics.</summary>
    public uint NumLeaves { get; set; }

    /// <summary>The doors from outdoors into the building's cells.</summary>
    public List<BuildingPortal> Portals { get; set; } = [];
}
