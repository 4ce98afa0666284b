namespace AcDream.Core.Dat;

/// <summary>A way into a building from outdoors: the door cell it leads to.</summary>
public sealed class BuildingPortal
{
    /// <summary>The portal's flags.</summary>
    public PortalFlags Flags { get; set; }

    /// <summary>Low 16 bits of the building's door cell in the same landblock.</summary>
    public ushort OtherCellId { get; set; }

    /// <summary>Index of the matching portal in the door cell's <see cref="EnvCell.CellPortals"/>.</summary>
    public ushort OtherPortalId { get; set; }

    /// <summary>Low 16 bits of the cells seen through this portal; not read by physics.</summary>
    public List<ushort> StabList { get; set; } = [];
}
