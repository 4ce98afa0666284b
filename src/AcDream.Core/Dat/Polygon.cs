namespace AcDream.Core.Dat;

/// <summary>
/// A planar polygon of a <see cref="CellStruct"/>. The plane is not stored: its normal is
/// <c>normalize(cross(v1 − v0, v2 − v0))</c>, so counter-clockwise seen from above faces +Z.
/// </summary>
public sealed class Polygon
{
    /// <summary>Vertex ids (keys of <see cref="VertexArray.Vertices"/>), in winding order.</summary>
    public List<short> VertexIds { get; set; } = [];

    /// <summary>Which faces exist.</summary>
    public CullMode SidesType { get; set; }

    /// <summary>Surface index of the front face.</summary>
    public short PosSurface { get; set; }

    /// <summary>Surface index of the back face, for two-sided polygons.</summary>
    public short NegSurface { get; set; }
}
