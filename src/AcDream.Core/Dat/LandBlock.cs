namespace AcDream.Core.Dat;

/// <summary>
/// An outdoor landblock as stored in the cell dat (file id <c>0xXXYYFFFF</c>): a 192 × 192 m
/// square of 8 × 8 outdoor cells of 24 m, on a 9 × 9 vertex grid.
/// </summary>
public sealed class LandBlock
{
    /// <summary>Number of vertices of the 9 × 9 grid, and the length of <see cref="Terrain"/> and <see cref="Height"/>.</summary>
    public const int VertexCount = 81;

    /// <summary>The landblock's dat id, <c>0xXXYYFFFF</c>: X west→east, Y south→north.</summary>
    public uint Id { get; set; }

    /// <summary>Whether the landblock has an object list (<c>0xXXYYFFFE</c>: buildings, statics).</summary>
    public bool HasObjects { get; set; }

    /// <summary>Per-vertex terrain type words (texture, road, scenery bits), x-major like <see cref="Height"/>.</summary>
    public ushort[] Terrain { get; set; } = new ushort[VertexCount];

    /// <summary>
    /// Per-vertex height indices, x-major: vertex (x, y) is <c>Height[x * 9 + y]</c>, placed at
    /// landblock-local (24·x, 24·y) metres. Each byte indexes the region's 256-entry height table.
    /// </summary>
    public byte[] Height { get; set; } = new byte[VertexCount];
}
