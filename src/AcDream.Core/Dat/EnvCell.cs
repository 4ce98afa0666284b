namespace AcDream.Core.Dat;

/// <summary>
/// An indoor cell (dat id <c>0xXXYYCCCC</c>, <c>CCCC</c> in 0x0100..0xFFFD): one room, corridor or
/// doorway of a building or dungeon, placed in its landblock by <see cref="Position"/>.
/// </summary>
public sealed class EnvCell
{
    /// <summary>The cell's full dat id, <c>0xXXYYCCCC</c>.</summary>
    public uint Id { get; set; }

    /// <summary>The cell's flags.</summary>
    public EnvCellFlags Flags { get; set; }

    /// <summary>Low 16 bits of the <see cref="Environment"/> id (<c>0x0D000000 | EnvironmentId</c>).</summary>
    public ushort EnvironmentId { get; set; }

    /// <summary>Key of the cell's <see cref="CellStruct"/> in <see cref="Environment.Cells"/>.</summary>
    public ushort CellStructure { get; set; }

    /// <summary>Cell-local → landblock-local placement (metres).</summary>
    public Frame Position { get; set; } = new();

    /// <summary>Connections to neighbouring cells; entry i pairs with <see cref="CellStruct.Portals"/>[i].</summary>
    public List<CellPortal> CellPortals { get; set; } = [];

    /// <summary>Objects inside this cell (e.g. the stairs between a room and its cellar), placed landblock-local.</summary>
    public List<Stab> StaticObjects { get; set; } = [];

    /// <summary>Low 16 bits of the cells visible from this one.</summary>
    public List<ushort> VisibleCells { get; set; } = [];
}
