namespace AcDream.Core.Dat;

/// <summary>The vertices of a <see cref="CellStruct"/>, keyed by vertex id.</summary>
public sealed class VertexArray
{
    /// <summary>Vertices by id; <see cref="Polygon.VertexIds"/> refer to these keys.</summary>
    public Dictionary<ushort, SWVertex> Vertices { get; set; } = [];
}
