using System.Numerics;
using System.Text.Json;
using AcDream.App.Movement;
using AcDream.App.World;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

// The page's data: the world's geometry near the walk and the walk's frames, as compact JSON. Lengths are whole
// millimetres (world metres × 1000, rounded); normals are thousandths; a column named in DeltaColumns holds its
// first value, then each value's difference from the one before.
internal static partial class WalkPage
{
    /// <summary>Terrain is sampled on a grid this many metres apart, over the walk's extent padded by <see cref="TerrainMargin"/>.</summary>
    internal const float TerrainStep = 2f;

    /// <summary>How far past the route and the creatures' paths the terrain patch reaches, metres.</summary>
    internal const float TerrainMargin = 15f;

    /// <summary>A physics polygon is a wall when its unit normal's |Z| is below this (as the SVG draws them).</summary>
    private const float WallMaxNormalZ = 0.2f;

    /// <summary>Writes the page's data for <paramref name="record"/> run in <paramref name="world"/>.</summary>
    private static void WriteData(Utf8JsonWriter json, WalkRecord record, HoltburgWorld world)
    {
        var frame = new PhysicsEngine(world.Center); // only its frame helpers: landblock-local to world metres
        MoverBody body = record.Scene.Effects.Body ?? MoverBody.Player;
        json.WriteStartObject();
        json.WriteString("name", record.Scene.Name);
        json.WriteNumber("fps", SceneRunner.FramesPerSecond);
        json.WriteNumber("radius", body.Radius);
        json.WriteNumber("height", body.Height);
        json.WriteNumber("eyeRadius", ChaseCamera.ViewerRadius);
        WriteNames<ResolveOutcome>(json, "outcomes");
        WriteNames<SurfaceKind>(json, "kinds");
        WriteCells(json, world, frame);
        WriteObjects(json, world, frame);
        WriteDoors(json, record, world);
        WriteTerrain(json, record, world, frame);
        WriteFrames(json, record);
        WriteDrawn(json, record);
        WriteCreatures(json, record);
        json.WriteEndObject();
    }

    /// <summary>The indoor cells: each one's floors (the triangles the engine samples) and its physics polygons, walls apart.</summary>
    private static void WriteCells(Utf8JsonWriter json, HoltburgWorld world, PhysicsEngine frame)
    {
        var floors = world.CellSurfaces.ToDictionary(s => s.CellId, s => s.GetFloorTriangles());
        json.WriteStartArray("cells");
        foreach (var cell in world.Cells)
        {
            Frame position = cell.EnvCell.Position;
            var polygons = cell.CellStruct.PhysicsPolygons.Values
                .Select(p => p.VertexIds.Select(id => frame.ToWorld(cell.CellId, position.Origin + Vector3.Transform(cell.CellStruct.VertexArray.Vertices[(ushort)id].Origin, position.Orientation))).ToArray())
                .Where(v => v.Length >= 3)
                .ToList();
            json.WriteStartObject();
            json.WriteString("id", Hex(cell.CellId));
            json.WriteString("name", HoltburgWorld.CellName(cell.CellId) ?? "");
            WritePoints(json, "floors", floors.TryGetValue(cell.CellId, out var triangles) ? triangles.SelectMany(t => new[] { t.A, t.B, t.C }).Select(v => frame.ToWorld(cell.CellId, v)) : []);
            WritePolygons(json, "walls", polygons.Where(IsWall));
            WritePolygons(json, "others", polygons.Where(v => !IsWall(v)));
            json.WriteEndObject();
        }

        json.WriteEndArray();
    }

    /// <summary>The objects (buildings' shells, stairs): walls as polygons or cylinders (bottom, top, radius), floors as triangles.</summary>
    private static void WriteObjects(Utf8JsonWriter json, HoltburgWorld world, PhysicsEngine frame)
    {
        Vector3 World(Vector3 local) => frame.ToWorld(world.Center, local);
        json.WriteStartArray("objects");
        foreach (ObjectSurface surface in world.ObjectSurfaces)
        {
            var walls = surface.GetWalls();
            json.WriteStartObject();
            json.WriteString("id", Hex(surface.ObjectId));
            json.WriteString("name", HoltburgWorld.ObjectName(surface.ObjectId) ?? "");
            json.WriteBoolean("building", surface.IsBuilding);
            WritePoints(json, "floors", surface.GetFloorTriangles().SelectMany(t => new[] { t.A, t.B, t.C }).Select(World));
            WritePolygons(json, "walls", walls.Where(w => w.Radius == 0f).Select(w => w.Outline.Select(World).ToArray()));
            json.WriteStartArray("cylinders");
            foreach (var wall in walls.Where(w => w.Radius > 0f))
            {
                json.WriteStartArray();
                WriteMillimetres(json, World(wall.Outline[0]));
                WriteMillimetres(json, World(wall.Outline[1]));
                json.WriteNumberValue(Millimetres(wall.Radius));
                json.WriteEndArray();
            }

            json.WriteEndArray();
            json.WriteEndObject();
        }

        json.WriteEndArray();
    }

    /// <summary>The scene's doors: each slab's polygons (world metres) and its states, from the frame each began.</summary>
    private static void WriteDoors(Utf8JsonWriter json, WalkRecord record, HoltburgWorld world)
    {
        json.WriteStartArray("doors");
        foreach (WorldDoor door in world.Doors.Values.Where(d => record.DoorChanges.Any(c => c.DoorId == d.Id)))
        {
            json.WriteStartObject();
            json.WriteString("id", Hex(door.Id));
            json.WriteString("name", HoltburgWorld.ObjectName(door.Id) ?? door.Name);
            WritePolygons(json, "polygons", door.Slab.PhysicsPolygons.Values.Select(p => p.VertexIds.Select(id => door.Position + Vector3.Transform(door.Slab.VertexArray.Vertices[(ushort)id].Origin, door.Orientation)).ToArray()));
            json.WriteStartArray("states");
            foreach (DoorChange change in record.DoorChanges.Where(c => c.DoorId == door.Id))
            {
                json.WriteStartArray();
                json.WriteNumberValue(change.Frame);
                json.WriteStringValue(change.State.ToString());
                json.WriteEndArray();
            }

            json.WriteEndArray();
            json.WriteEndObject();
        }

        json.WriteEndArray();
    }

    /// <summary>
    /// The terrain under the walk: heights on a grid <see cref="TerrainStep"/> apart from (x0, y0), nx × ny points,
    /// row by row (x fastest), delta-coded millimetres; past the world's edge the edge landblock's terrain, clamped.
    /// </summary>
    private static void WriteTerrain(Utf8JsonWriter json, WalkRecord record, HoltburgWorld world, PhysicsEngine frame)
    {
        Vector3[] drawn = [.. record.Samples.Select(s => s.Position), .. record.Creatures.SelectMany(c => c.Samples).Select(s => s.Position)];
        float x0 = MathF.Floor(drawn.Min(p => p.X) - TerrainMargin), y0 = MathF.Floor(drawn.Min(p => p.Y) - TerrainMargin);
        int nx = (int)MathF.Ceiling((drawn.Max(p => p.X) + TerrainMargin - x0) / TerrainStep) + 1;
        int ny = (int)MathF.Ceiling((drawn.Max(p => p.Y) + TerrainMargin - y0) / TerrainStep) + 1;
        var terrains = new Dictionary<uint, TerrainSurface>();
        var heights = new List<int>(nx * ny);
        for (int j = 0; j < ny; j++)
        {
            for (int i = 0; i < nx; i++)
            {
                var at = new Vector3(x0 + (i * TerrainStep), y0 + (j * TerrainStep), 0f);
                uint id = frame.LandblockAt(at);
                if (!terrains.TryGetValue(id, out TerrainSurface? terrain))
                {
                    terrains[id] = terrain = world.Terrain(id);
                }

                Vector3 local = frame.ToLandblockLocal(id, at);
                heights.Add(Millimetres(terrain.SampleZ(local.X, local.Y)));
            }
        }

        json.WriteStartObject("terrain");
        json.WriteNumber("x0", x0);
        json.WriteNumber("y0", y0);
        json.WriteNumber("step", TerrainStep);
        json.WriteNumber("nx", nx);
        json.WriteNumber("ny", ny);
        WriteDeltas(json, "z", heights);
        json.WriteEndObject();
    }

    /// <summary>
    /// The player's frames, one value per frame in each column: frame number, feet and the chase camera's eye (delta-coded
    /// millimetres), cell (index into "cellIds"), on the ground (0/1), outcome (index into "outcomes": the refusal's when the
    /// engine refused a step, else Slid when a step slid, else Moved), and what the frame's steps met (<see cref="MoveReport"/>):
    /// the floor's and the wall's kind (index into "kinds"), id (index into "ids") and normal (x, y, z in thousandths).
    /// </summary>
    private static void WriteFrames(Utf8JsonWriter json, WalkRecord record)
    {
        IReadOnlyList<FrameSample> samples = record.Samples;
        var cellIds = samples.Select(s => s.CellId).Distinct().ToList();
        var ids = samples.SelectMany(s => new[] { s.Moved.Met.Floor.Id, s.Moved.Met.Wall.Id }).Distinct().ToList();
        json.WriteStartObject("frames");
        json.WriteNumber("count", samples.Count);
        WriteDeltas(json, "frame", samples.Select(s => s.Frame));
        WriteDeltas(json, "x", samples.Select(s => Millimetres(s.Position.X)));
        WriteDeltas(json, "y", samples.Select(s => Millimetres(s.Position.Y)));
        WriteDeltas(json, "z", samples.Select(s => Millimetres(s.Position.Z)));
        WriteDeltas(json, "eyeX", samples.Select(s => Millimetres(s.Camera.Eye.X)));
        WriteDeltas(json, "eyeY", samples.Select(s => Millimetres(s.Camera.Eye.Y)));
        WriteDeltas(json, "eyeZ", samples.Select(s => Millimetres(s.Camera.Eye.Z)));
        WriteStrings(json, "cellIds", cellIds.Select(Hex));
        WriteStrings(json, "cellNames", cellIds.Select(id => HoltburgWorld.CellName(id) ?? ""));
        WriteInts(json, "cell", samples.Select(s => cellIds.IndexOf(s.CellId)));
        WriteInts(json, "ground", samples.Select(s => s.IsOnGround ? 1 : 0));
        WriteInts(json, "outcome", samples.Select(s => (int)Outcome(s)));
        WriteStrings(json, "ids", ids.Select(Hex));
        WriteContacts(json, "floor", samples.Select(s => s.Moved.Met.Floor), ids);
        WriteContacts(json, "wall", samples.Select(s => s.Moved.Met.Wall), ids);
        json.WriteEndObject();
    }

    /// <summary>
    /// What the player's moves saw, as the engine drew it (<see cref="WalkRecord.Drawn"/>), in frame order: each segment's
    /// frame (delta-coded), kind (index into "drawKinds") and ends (x, y, z of each, whole millimetres, in "ends", six a
    /// segment).
    /// </summary>
    private static void WriteDrawn(Utf8JsonWriter json, WalkRecord record)
    {
        json.WriteStartObject("drawn");
        WriteNames<DrawKind>(json, "kinds");
        WriteDeltas(json, "frame", record.Drawn.Select(l => l.Frame));
        WriteInts(json, "kind", record.Drawn.Select(l => (int)l.Kind));
        WriteInts(json, "ends", record.Drawn.SelectMany(l => new[] { l.A.X, l.A.Y, l.A.Z, l.B.X, l.B.Y, l.B.Z }).Select(Millimetres));
        json.WriteEndObject();
    }

    /// <summary>The frame's outcome as the page shows it: the engine's refusal, else Slid when a step slid, else Moved.</summary>
    internal static ResolveOutcome Outcome(FrameSample sample) =>
        sample.Refusal ?? (sample.Slide is not null ? ResolveOutcome.Slid : ResolveOutcome.Moved);

    private static void WriteContacts(Utf8JsonWriter json, string name, IEnumerable<SurfaceContact> contacts, List<uint> ids)
    {
        var list = contacts.ToList();
        WriteInts(json, name + "Kind", list.Select(c => (int)c.Kind));
        WriteInts(json, name + "Id", list.Select(c => ids.IndexOf(c.Id)));
        WriteInts(json, name + "Normal", list.SelectMany(c => new[] { c.Normal.X, c.Normal.Y, c.Normal.Z }).Select(Millimetres));
    }

    /// <summary>Each creature's samples: frame, feet (delta-coded, millimetres).</summary>
    private static void WriteCreatures(Utf8JsonWriter json, WalkRecord record)
    {
        json.WriteStartArray("creatures");
        foreach (CreaturePath creature in record.Creatures.Where(c => c.Samples.Count > 0))
        {
            json.WriteStartObject();
            json.WriteString("id", Hex(creature.Id));
            WriteDeltas(json, "frame", creature.Samples.Select(s => s.Frame));
            WriteDeltas(json, "x", creature.Samples.Select(s => Millimetres(s.Position.X)));
            WriteDeltas(json, "y", creature.Samples.Select(s => Millimetres(s.Position.Y)));
            WriteDeltas(json, "z", creature.Samples.Select(s => Millimetres(s.Position.Z)));
            json.WriteEndObject();
        }

        json.WriteEndArray();
    }

    private static bool IsWall(Vector3[] v) => MathF.Abs(Vector3.Normalize(Vector3.Cross(v[1] - v[0], v[2] - v[0])).Z) < WallMaxNormalZ;

    /// <summary>Metres to whole millimetres, rounded half away from zero.</summary>
    internal static int Millimetres(float metres) => (int)Math.Round(metres * 1000.0, MidpointRounding.AwayFromZero);

    private static string Hex(uint id) => $"0x{id:X8}";

    private static void WriteNames<T>(Utf8JsonWriter json, string name)
        where T : struct, Enum => WriteStrings(json, name, Enum.GetValues<T>().OrderBy(v => Convert.ToInt32(v, System.Globalization.CultureInfo.InvariantCulture)).Select(v => v.ToString()));

    private static void WriteStrings(Utf8JsonWriter json, string name, IEnumerable<string> values)
    {
        json.WriteStartArray(name);
        foreach (string value in values)
        {
            json.WriteStringValue(value);
        }

        json.WriteEndArray();
    }

    private static void WriteInts(Utf8JsonWriter json, string name, IEnumerable<int> values)
    {
        json.WriteStartArray(name);
        foreach (int value in values)
        {
            json.WriteNumberValue(value);
        }

        json.WriteEndArray();
    }

    /// <summary>The first value, then each one's difference from the one before.</summary>
    private static void WriteDeltas(Utf8JsonWriter json, string name, IEnumerable<int> values)
    {
        int previous = 0;
        WriteInts(json, name, values.Select(v => (v - previous, previous = v).Item1));
    }

    private static void WriteMillimetres(Utf8JsonWriter json, Vector3 p)
    {
        json.WriteNumberValue(Millimetres(p.X));
        json.WriteNumberValue(Millimetres(p.Y));
        json.WriteNumberValue(Millimetres(p.Z));
    }

    /// <summary>Points as one flat array of millimetres (x, y, z, x, y, z, …).</summary>
    private static void WritePoints(Utf8JsonWriter json, string name, IEnumerable<Vector3> points)
    {
        json.WriteStartArray(name);
        foreach (Vector3 p in points)
        {
            WriteMillimetres(json, p);
        }

        json.WriteEndArray();
    }

    /// <summary>Polygons, each a flat array of millimetres.</summary>
    private static void WritePolygons(Utf8JsonWriter json, string name, IEnumerable<Vector3[]> polygons)
    {
        json.WriteStartArray(name);
        foreach (Vector3[] polygon in polygons)
        {
            json.WriteStartArray();
            foreach (Vector3 p in polygon)
            {
                WriteMillimetres(json, p);
            }

            json.WriteEndArray();
        }

        json.WriteEndArray();
    }
}
