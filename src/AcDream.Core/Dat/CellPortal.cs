namespace AcDream.Core.Dat;

/// <summary>One portal of an <see cref="EnvCell"/>: an opening into a neighbouring cell or the outdoors.</summary>
public sealed class CellPortal
{
    /// <summary>The portal's flags.</summary>
    public PortalFlags Flags { get; set; }

    /// <summary>Key of the portal's polygon in <see cref="CellStruct.Polygons"/> (the drawing polygons).</summary>
    public ushort PolygonId { get; set; }

    /// <summary>Low 16 bits of the neighbour cell's id in the same landblock; <c>0xFFFF</c> means the outdoors.</summary>
    public ushort OtherCellId { get; set; }

    /// <summary>Index of the matching portal in the neighbour's <see cref="EnvCell.CellPortals"/>.</summary>
    public ushort OtherPortalId { get; set; }
}
