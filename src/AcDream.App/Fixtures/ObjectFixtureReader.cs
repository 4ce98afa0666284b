using System.Globalization;
using System.Text.Json;
using AcDream.Core.Dat;

namespace AcDream.App.Fixtures;

/// <summary>
/// Reads the object fixtures (one GfxObj per JSON file, the format of <c>Fixtures/objects/README.md</c>)
/// into the dat model, 1:1: the physics polygons become <see cref="GfxObj.PhysicsPolygons"/> (keyed by
/// their ids) over one shared vertex array, the bounding sphere <see cref="GfxObj.BoundingSphere"/>.
/// The stored normals and plane distances are not read: the engine takes a polygon's normal from its
/// winding, which the fixtures' README checked against them.
/// </summary>
public static class ObjectFixtureReader
{
    /// <summary>Parses one fixture file's text; <paramref name="source"/> names it in errors.</summary>
    /// <exception cref="InvalidDataException">The text is not a fixture object; the message names the source and field.</exception>
    public static GfxObj Read(string json, string source)
    {
        try
        {
            using JsonDocument document = JsonDocument.Parse(json);
            JsonElement root = document.RootElement;
            var gfxObj = new GfxObj
            {
                Id = uint.Parse(root.GetProperty("gfxObjId").GetString()!.AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture),
                Flags = GfxObjFlags.HasPhysics,
            };
            JsonElement sphere = root.GetProperty("boundingSphere");
            gfxObj.BoundingSphere = new Sphere { Origin = CellFixtureReader.ReadVector(sphere.GetProperty("origin")), Radius = sphere.GetProperty("radius").GetSingle() };
            CellFixtureReader.ReadPolygons(root.GetProperty("physicsPolygons"), gfxObj.PhysicsPolygons, gfxObj.VertexArray, []);

            return gfxObj;
        }
        catch (Exception e) when (e is JsonException or KeyNotFoundException or InvalidOperationException or FormatException or OverflowException or IndexOutOfRangeException or NullReferenceException or ArgumentException)
        {
            throw new InvalidDataException($"{source}: not a fixture object ({e.Message})", e);
        }
    }
}
