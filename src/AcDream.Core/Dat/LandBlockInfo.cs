namespace AcDream.Core.Dat;

/// <summary>
/// What stands in a landblock besides its terrain (cell dat id <c>0xXXYYFFFE</c>): its static
/// objects outdoors and its buildings.
/// </summary>
public sealed class LandBlockInfo
{
    /// <summary>The dat id, <c>0xXXYYFFFE</c>.</summary>
    public uint Id { get; set; }

    /// <summary>Number of indoor cells of the landblock (ids 0x0100 up).</summary>
    public uint NumCells { get; set; }

    /// <summary>Static objects outdoors: trees, rocks, fences, outdoor stairs.</summary>
    public List<Stab> Objects { get; set; } = [];

    /// <summary>The buildings, each with its shell and doors.</summary>
    public List<BuildingInfo> Buildings { get; set; } = [];

    /// <summary>Restrictions by cell (housing); not read by physics.</summary>
    public Dictionary<uint, uint> RestrictionTable { get; set; } = [];
}
