using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.App.Fixtures;

/// <summary>
/// Reads the Holtburg cell fixtures (one EnvCell per JSON file, the format of
/// <c>Fixtures/holtburg-cells/README.md</c>) into the dat model, 1:1: the physics and drawing
/// polygons become <see cref="CellStruct.PhysicsPolygons"/> and <see cref="CellStruct.Polygons"/>
/// over one shared vertex array, the portals become <see cref="EnvCell.CellPortals"/>, the row-major
/// rotation becomes the <see cref="Frame.Orientation"/> quaternion.
/// </summary>
public static class CellFixtureReader
{
    /// <summary>One fixture cell in the dat model.</summary>
    public sealed record FixtureCell(uint CellId, EnvCell EnvCell, CellStruct CellStruct);

    /// <summary>Parses one fixture file's text; <paramref name="source"/> names it in errors.</summary>
    /// <exception cref="InvalidDataException">The text is not a fixture cell; the message names the source and field.</exception>
    public static FixtureCell Read(string json, string source)
    {
        try
        {
            using JsonDocument document = JsonDocument.Parse(json);
            JsonElement root = document.RootElement;
            uint cellId = uint.Parse(root.GetProperty("cellId").GetString()!.AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture);
            Vector3 origin = ReadVector(root.GetProperty("origin"));
            JsonElement rotation = root.GetProperty("rotation");
            Vector3 r0 = ReadVector(rotation[0]), r1 = ReadVector(rotation[1]), r2 = ReadVector(rotation[2]);
            var matrix = new Matrix4x4(r0.X, r0.Y, r0.Z, 0, r1.X, r1.Y, r1.Z, 0, r2.X, r2.Y, r2.Z, 0, 0, 0, 0, 1);

            var cellStruct = new CellStruct();
            var vertexIds = new Dictionary<Vector3, short>();
            ReadPolygons(root.GetProperty("physicsPolygons"), cellStruct.PhysicsPolygons, cellStruct.VertexArray, vertexIds);
            ReadPolygons(root.GetProperty("drawingPolygons"), cellStruct.Polygons, cellStruct.VertexArray, vertexIds);

            var envCell = new EnvCell
            {
                Id = cellId,
                Position = new Frame { Origin = origin, Orientation = Quaternion.CreateFromRotationMatrix(matrix) },
            };
            foreach (JsonElement portal in root.GetProperty("portals").EnumerateArray())
            {
                ushort polygonId = portal.GetProperty("polygonId").GetUInt16();
                cellStruct.Portals.Add(polygonId);
                envCell.CellPortals.Add(new CellPortal
                {
                    OtherCellId = portal.GetProperty("otherCellId").GetUInt16(),
                    PolygonId = polygonId,
                    Flags = (PortalFlags)portal.GetProperty("flags").GetUInt16(),
                });
            }

            foreach (JsonElement visible in root.GetProperty("visibleCells").EnumerateArray())
            {
                envCell.VisibleCells.Add(CellIds.CellNumber(uint.Parse(visible.GetString()!.AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture)));
            }

            return new FixtureCell(cellId, envCell, cellStruct);
        }
        catch (Exception e) when (e is JsonException or KeyNotFoundException or InvalidOperationException or FormatException or OverflowException or IndexOutOfRangeException or NullReferenceException)
        {
            throw new InvalidDataException($"{source}: not a fixture cell ({e.Message})", e);
        }
    }

    /// <summary>Reads a fixture's polygon list (id, sidesType, vertices) into <paramref name="into"/>, sharing equal vertices through <paramref name="vertexIds"/>.</summary>
    internal static void ReadPolygons(JsonElement list, Dictionary<ushort, Polygon> into, VertexArray vertexArray, Dictionary<Vector3, short> vertexIds)
    {
        foreach (JsonElement element in list.EnumerateArray())
        {
            var polygon = new Polygon { SidesType = (CullMode)element.GetProperty("sidesType").GetInt32() };
            foreach (JsonElement vertex in element.GetProperty("vertices").EnumerateArray())
            {
                Vector3 position = ReadVector(vertex);
                if (!vertexIds.TryGetValue(position, out short id))
                {
                    id = (short)vertexIds.Count;
                    vertexIds.Add(position, id);
                    vertexArray.Vertices.Add((ushort)id, new SWVertex { Origin = position });
                }

                polygon.VertexIds.Add(id);
            }

            into.Add(element.GetProperty("id").GetUInt16(), polygon);
        }
    }

    /// <summary>A JSON array [x, y, z] as a vector.</summary>
    internal static Vector3 ReadVector(JsonElement array) =>
        new(array[0].GetSingle(), array[1].GetSingle(), array[2].GetSingle());
}
