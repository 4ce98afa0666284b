using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Testing;

// Shared by the test and benchmark projects (linked, not referenced): one builder of fake dat data.

/// <summary>Builds an <see cref="EnvCell"/> + <see cref="CellStruct"/> from cell-local polygons.</summary>
internal sealed class CellBuilder
{
    private readonly Dictionary<Vector3, short> _vertexIds = [];
    private ushort _nextPhysics;
    private ushort _nextDrawing;

    public CellBuilder(uint cellId, Vector3 origin = default, Quaternion? orientation = null)
    {
        CellId = cellId;
        EnvCell = new EnvCell
        {
            Id = cellId,
            Position = new Frame { Origin = origin, Orientation = orientation ?? Quaternion.Identity },
        };
    }

    public uint CellId { get; }

    public EnvCell EnvCell { get; }

    public CellStruct CellStruct { get; } = new();

    /// <summary>Adds a physics polygon (floor, wall or ceiling, by its winding).</summary>
    public CellBuilder Physics(params Vector3[] vertices)
    {
        CellStruct.PhysicsPolygons.Add(_nextPhysics++, MakePolygon(vertices));
        return this;
    }

    public CellBuilder Floor(float minX, float minY, float maxX, float maxY, float z) =>
        Physics(Square(minX, minY, maxX, maxY, z));

    /// <summary>LandBlock.Height bytes (81, x-major) from a function of the vertex indices (x, y).</summary>
    public static byte[] Heights(Func<int, int, int> height)
    {
        var heights = new byte[81];
        for (int x = 0; x < 9; x++)
        {
            for (int y = 0; y < 9; y++)
            {
                heights[(x * 9) + y] = checked((byte)height(x, y));
            }
        }

        return heights;
    }

    /// <summary>A horizontal rectangle, counter-clockwise seen from above (normal +Z), cell-local.</summary>
    public static Vector3[] Square(float minX, float minY, float maxX, float maxY, float z) =>
        [new(minX, minY, z), new(maxX, minY, z), new(maxX, maxY, z), new(minX, maxY, z)];

    /// <summary>
    /// Adds a portal polygon to <paramref name="otherCell"/> (low 16 bits, 0xFFFF outdoors). The side
    /// flag is set from <paramref name="cellSide"/>, a point inside this cell (cell-local).
    /// </summary>
    public CellBuilder Portal(ushort otherCell, Vector3 cellSide, params Vector3[] vertices)
    {
        ushort id = (ushort)(1000 + _nextDrawing++);
        CellStruct.Polygons.Add(id, MakePolygon(vertices));
        CellStruct.Portals.Add(id);
        Vector3 normal = Vector3.Normalize(Vector3.Cross(vertices[1] - vertices[0], vertices[2] - vertices[0]));
        bool positive = Vector3.Dot(normal, cellSide - vertices[0]) > 0f;
        EnvCell.CellPortals.Add(new CellPortal
        {
            OtherCellId = otherCell,
            PolygonId = id,
            Flags = PortalFlags.ExactMatch | (positive ? PortalFlags.PortalSide : PortalFlags.None),
        });
        return this;
    }

    public CellSurface Build() => new(CellId, EnvCell, CellStruct);

    private Polygon MakePolygon(Vector3[] vertices)
    {
        var polygon = new Polygon();
        foreach (Vector3 v in vertices)
        {
            if (!_vertexIds.TryGetValue(v, out short id))
            {
                id = (short)_vertexIds.Count;
                _vertexIds.Add(v, id);
                CellStruct.VertexArray.Vertices.Add((ushort)id, new SWVertex { Origin = v });
            }

            polygon.VertexIds.Add(id);
        }

        return polygon;
    }
}
