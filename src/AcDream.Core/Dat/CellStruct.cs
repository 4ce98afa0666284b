namespace AcDream.Core.Dat;

/// <summary>The geometry of one cell shape of an <see cref="Environment"/>, in cell-local metres.</summary>
public sealed class CellStruct
{
    /// <summary>The vertices all polygons refer to.</summary>
    public VertexArray VertexArray { get; set; } = new();

    /// <summary>The drawing polygons, including the portal openings that <see cref="Portals"/> and <see cref="CellPortal.PolygonId"/> name.</summary>
    public Dictionary<ushort, Polygon> Polygons { get; set; } = [];

    /// <summary>Polygon id (key of <see cref="Polygons"/>) of each portal, in the order of <see cref="EnvCell.CellPortals"/>.</summary>
    public List<ushort> Portals { get; set; } = [];

    /// <summary>The collision polygons: floors, walls and ceilings together.</summary>
    public Dictionary<ushort, Polygon> PhysicsPolygons { get; set; } = [];
}
