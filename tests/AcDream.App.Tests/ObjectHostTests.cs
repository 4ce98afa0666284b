using System.Numerics;
using System.Xml.Linq;
using AcDream.App.Fixtures;
using AcDream.App.Scenes;
using AcDream.App.Streaming;
using AcDream.App.World;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.App.Tests;

/// <summary>Objects on the host side: the streaming path registers them, scenes choose them, the summary and the SVG show them.</summary>
public class ObjectHostTests
{
    private const uint Holtburg = HoltburgWorld.Holtburg;
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    // On the small building's plinth (top at 96 m), in front of its doorway: landblock-local (156.25, 35.41).
    private static readonly Vector3 OnPlinth = new(156.25f, 35.41f, 96f);

    [Fact]
    public void ApplyLoadedTerrain_WithObjects_RegistersThemAndUnloadRemovesThem()
    {
        var world = new HoltburgWorld(HoltburgWorld.Worlds.Holtburg, ["cottage", "small-building"]);
        var warnings = new List<string>();
        using var window = new GameWindow(world, world.HeightTable, Holtburg, warnings.Add);

        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out string? error).Should().BeTrue($"error: {error}");

        warnings.Should().BeEmpty();
        window.ObjectCounts[Holtburg].Should().Be(2, "the cottage's shell and the small building");
        window.Physics.TryGetGround(OnPlinth, 0xA9B40001u, 0.5f, out float z, out _, out uint objectId).Should().BeTrue();
        objectId.Should().Be(ObjectPlacements.SmallBuilding, "the plinth is the small building's floor");
        z.Should().BeApproximately(96f, 1e-3f);

        // Outdoors, 1 m west of the cottage shell's main-block west wall (x 136.3) south of the door, walking east into it.
        ResolveResult wall = window.Physics.Resolve(new Vector3(135.8f, 3.9f, 94f), 0xA9B40001u, new Vector3(1f, 0f, 0f), 0.5f, default, out MoveReport met);
        wall.Position.X.Should().BeLessThan(136.3f, $"the shell's wall stops the move, got {wall.Position} ({wall.Outcome})");
        met.Wall.Should().Be(new SurfaceContact(SurfaceKind.BuildingShell, ObjectPlacements.CottageShell, wall.SurfaceNormal), $"{wall}");

        ResolveResult door = window.Physics.Resolve(new Vector3(135.5f, 5.15f, 94f), 0xA9B40001u, new Vector3(1f, 0f, 0f), 0.5f);
        door.CellId.Should().Be(0xA9B40145u, "the shell's door opening still leads into the door cell");

        window.UnloadLandblockLocked(Holtburg);
        window.ObjectCounts.Should().NotContainKey(Holtburg);
        window.Physics.TryGetGround(OnPlinth, 0xA9B40001u, 0.5f, out _, out _, out _).Should().BeFalse("the landblock and its objects are gone");
    }

    [Fact]
    public void ApplyLoadedTerrain_BadObjects_AreReportedAndSkippedTheRestRegisters()
    {
        var world = new HoltburgWorld(HoltburgWorld.Worlds.Holtburg, ["cottage", "small-building"]);
        var warnings = new List<string>();
        using var window = new GameWindow(world, world.HeightTable, Holtburg, warnings.Add);
        LoadedLandblock real = world.Load(Holtburg);
        LandBlockInfo info = real.Info!;
        info.Objects.Add(new Stab { Id = 0x01999999u, Frame = new Frame { Origin = new Vector3(100f, 100f, 94f) } }); // not among the GfxObjs
        info.Objects.Add(new Stab { Id = 0x05000001u }); // not a GfxObj or Setup id
        info.Buildings.Add(new BuildingInfo { ModelId = ObjectPlacements.SmallBuilding, Portals = [new BuildingPortal { OtherCellId = 0x0199 }] }); // door cell not registered
        var cells = real.EnvCells.Select(c => c).ToList();
        EnvCell cellar = cells.Single(c => c.Id == 0xA9B40147u);
        var cellarWithObject = new EnvCell { Id = cellar.Id, EnvironmentId = cellar.EnvironmentId, CellStructure = cellar.CellStructure, Position = cellar.Position, CellPortals = cellar.CellPortals, StaticObjects = [new Stab { Id = 0x01888888u }] };
        cells[cells.IndexOf(cellar)] = cellarWithObject;
        cells.Add(new EnvCell { Id = 0xA9B40190u, EnvironmentId = 0x0190, StaticObjects = [new Stab { Id = ObjectPlacements.StairPiece }] }); // its cell does not build

        window.ApplyLoadedTerrainLocked(Holtburg, real with { EnvCells = cells }, out string? error).Should().BeTrue($"a bad object is not fatal; error: {error}");

        string all = string.Join(" | ", warnings);
        warnings.Should().Contain(w => w.Contains("object 0 (0x01999999)") && w.Contains("skipped"), all);
        warnings.Should().Contain(w => w.Contains("object 1 (0x05000001)") && w.Contains("skipped"), all);
        warnings.Should().ContainSingle(w => w.Contains("object 0x01000F69 skipped (DoorCellNotGiven)") && w.Contains("door cell 0xA9B40199"), all);
        warnings.Should().Contain(w => w.Contains("object 0 (0x01888888) of cell 0xA9B40147") && w.Contains("skipped"), all);
        warnings.Should().Contain(w => w.Contains("cell 0xA9B40190") && w.Contains("skipped with their cell"), all);
        window.ObjectCounts[Holtburg].Should().Be(2, "the two good buildings are registered");
        window.Physics.TryGetGround(OnPlinth, 0xA9B40001u, 0.5f, out _, out _, out uint objectId).Should().BeTrue();
        objectId.Should().Be(ObjectPlacements.SmallBuilding);
    }

    [Fact]
    public void ApplyLoadedTerrain_CellarStairs_AreRegisteredInTheirCells()
    {
        var world = new HoltburgWorld(HoltburgWorld.Worlds.Holtburg, ["cellar-stairs"]);
        var warnings = new List<string>();
        using var window = new GameWindow(world, world.HeightTable, Holtburg, warnings.Add);

        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out string? error).Should().BeTrue($"error: {error}");

        warnings.Should().BeEmpty();
        window.ObjectCounts[Holtburg].Should().Be(2, "one stair in each cellar");
        world.Load(Holtburg).EnvCells.Single(c => c.Id == ObjectPlacements.CottageCellar).StaticObjects.Should().ContainSingle(o => o.Id == ObjectPlacements.CottageCellarStair);
        window.Physics.TryGetGround(new Vector3(141.3f, 7.25f, 92f), ObjectPlacements.CottageCellar, 0.6f, out float z, out _, out uint objectId).Should().BeTrue();
        objectId.Should().Be(ObjectPlacements.CottageCellarStair, "the stair stands in the cottage's cellar");
        z.Should().BeInRange(92f, 93f, "half way up the ramp from 91 m to 94 m");
        window.Physics.TryGetGround(new Vector3(141.3f, 7.25f, 92f), 0xA9B40001u, 0.6f, out _, out _, out uint outdoors).Should().BeTrue();
        outdoors.Should().Be(0u, "a cell's object is not an outdoor one");
    }

    [Fact]
    public void UpdateStreaming_RegistersTheWorldsObjectsWithTheirLandblock()
    {
        var world = new HoltburgWorld(HoltburgWorld.Worlds.Staircase, ["staircase"]);
        using var window = new GameWindow(world, world.HeightTable, world.Center);
        var at = new Vector3(132f, 77f, 0f);
        window.UpdateStreaming(at);
        window.WaitForLoads(TimeSpan.FromSeconds(20)).Should().BeTrue();
        window.UpdateStreaming(at);

        window.ObjectCounts[HoltburgWorld.StaircaseLandblock].Should().Be(8, "the eight stair pieces");
        window.ObjectCounts.Where(c => c.Key != HoltburgWorld.StaircaseLandblock).Should().OnlyContain(c => c.Value == 0);
        window.Physics.TryGetGround(at with { Z = 60.6f }, 0u, 0.5f, out float z, out _, out uint objectId).Should().BeTrue();
        objectId.Should().Be(ObjectPlacements.StairPiece);
        z.Should().BeApproximately(59.015f + (0.8f * (77f - 74.995f)), 1e-3f, "the treads' one ramp");
    }

    [Fact]
    public void StaircaseScene_ClimbsToTheTopTreadAndBackDown_OnTheStairPieces()
    {
        Scene scene = SceneReader.ReadFile(Path.Combine(TestWorlds.RepositoryRoot(), "src", "AcDream.App", "Scenes", "outdoor-staircase.json"));
        WalkRecord record = SceneRunner.Run(scene);

        record.Legs.Should().OnlyContain(l => l.Reached, string.Join(", ", record.Legs.Select(l => $"{l.Leg.Name}: {l.Reached}")));
        float top = record.Samples.Max(s => s.Position.Z);
        top.Should().BeGreaterThan(62.0f, "the top tread is at 62.215 m where it ends (y 78.995); the walk stops at y 78.8");
        FrameSample highest = record.Samples.First(s => s.Position.Z == top);
        highest.FloorObjectId.Should().Be(ObjectPlacements.StairPiece);
        highest.IsOnGround.Should().BeTrue();
        record.AirborneFrames.Should().Be(0, "up and down on foot");
        record.Final.Position.Z.Should().BeApproximately(HoltburgWorld.StaircaseFlatZ, 1e-3f, "back on the flat land");

        // Beside the treads (the body's centre 0.2 m past their east edge), the treads under its edge hold it: it climbs.
        LegResult beside = record.Legs.Single(l => l.Leg.Name.StartsWith("north beside the treads", StringComparison.Ordinal));
        FrameSample[] climb = record.Samples.Where(s => s.Frame >= beside.FirstFrame && s.Frame <= beside.LastFrame).ToArray();
        climb.Should().OnlyContain(s => s.IsOnGround && s.Position.X == 132.95f, "on foot, its centre beside the treads");
        climb.Max(s => s.Position.Z).Should().BeGreaterThan(61.7f, "it climbed beside them");
        climb.Should().Contain(s => s.FloorObjectId == ObjectPlacements.StairPiece, "held by the stair pieces");

        string summary = WalkReport.Format(record, "x.svg");
        summary.Should().Contain("Objects: staircase (world staircase); registered 8 in 0xF682.");
        summary.Should().MatchRegex(@"Object floors stood on: 0x01000AC5 stair piece: \d+ frames");
    }

    [Fact]
    public void DefaultScene_Summary_NamesTheObjectFloorsAndWallsItMet()
    {
        WalkRecord record = SceneRunner.Run(SceneReader.ReadDefault());

        record.Samples.Should().Contain(s => s.FloorObjectId == ObjectPlacements.SmallBuilding, "the walk goes up the small building's ramp");
        record.Samples.Should().Contain(s => s.WallObjectId == ObjectPlacements.CottageShell, "the body slides along the shell at the west door");
        string summary = WalkReport.Format(record, "x.svg");
        summary.Should().Contain("Objects: cottage, small-building, cellar-stairs (world holtburg); registered 4 in 0xA9B4.");
        summary.Should().MatchRegex(@"Object floors stood on: [^\n]*0x01FFF147 cottage cellar stair: \d+ frames");
        summary.Should().MatchRegex(@"Object floors stood on: [^\n]*0x01FFF174 building B cellar stair: \d+ frames");
        summary.Should().MatchRegex(@"Object floors stood on: [^\n]*0x01000F69 small building: \d+ frames");
        summary.Should().MatchRegex(@"Object walls met: [^\n]*0x01000A2B cottage shell: \d+ frames \(\d+ × slid");
    }

    [Fact]
    public void WalkSvg_DrawsEachObjectsFloorsAndWallsFromTheEngine()
    {
        Scene scene = SceneReader.ReadDefault();
        HoltburgWorld world = scene.CreateWorld();
        WalkRecord record = SceneRunner.Run(scene, world, maxFrames: 1);

        XDocument svg = WalkSvg.Build(record, world);

        XElement objects = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "objects");
        var groups = objects.Elements(Svg + "g").ToList();
        groups.Select(g => (string?)g.Attribute("data-object-id")).Should().Equal("0x01000A2B", "0x01000F69", "0x01FFF147", "0x01FFF174");
        for (int i = 0; i < groups.Count; i++)
        {
            ObjectSurface surface = world.ObjectSurfaces[i];
            string which = $"object {i} ({groups[i].Attribute("data-object-id")?.Value}, surface 0x{surface.ObjectId:X8})";
            groups[i].Elements().Count(e => (string?)e.Attribute("class") == "object-floor").Should().Be(surface.GetFloorTriangles().Length, $"{which}: one drawn floor per floor triangle");
            groups[i].Elements().Count(e => (string?)e.Attribute("class") == "object-wall").Should().Be(surface.GetWalls().Length, $"{which}: one drawn wall per wall");
        }

        groups[1].Elements().Count(e => (string?)e.Attribute("class") == "object-floor").Should().BePositive("the plinth and ramp are floors");
        objects.Attribute("stroke")!.Value.Should().NotBe("#555", "objects are drawn apart from the cells' walls");
        svg.Descendants(Svg + "text").Should().Contain(t => t.Value.Contains("objects (0x01000A2B cottage shell, 0x01000F69 small building, 0x01FFF147 cottage cellar stair, 0x01FFF174 building B cellar stair)"));
    }

    [Theory]
    [InlineData("\"world\": \"moon\",", "field world: must be \"holtburg\" or \"staircase\"")]
    [InlineData("\"objects\": \"cottage\",", "field objects: must be an array")]
    [InlineData("\"objects\": [\"tree\"],", "field objects[0]: must be one of the holtburg world's object sets")]
    [InlineData("\"objects\": [\"staircase\"],", "field objects[0]: must be one of the holtburg world's object sets")]
    [InlineData("\"objects\": [\"cottage\", \"cottage\"],", "field objects[1]: is listed twice")]
    public void SceneReader_BadWorldOrObjects_NamesTheField(string field, string expected)
    {
        string json = $$"""{ "name": "x", {{field}} "start": { "position": [0, 0] }, "legs": [ { "name": "a", "to": [1, 0] } ] }""";
        Action read = () => SceneReader.Parse(json, "test");
        read.Should().Throw<SceneFormatException>().WithMessage($"*{expected}*");
    }

    [Fact]
    public void SceneRunner_WorldOfAnotherScene_IsRefused()
    {
        Action run = () => SceneRunner.Run(SceneReader.ReadDefault(), new HoltburgWorld(), maxFrames: 1);
        run.Should().Throw<ArgumentException>().WithMessage("*cottage*");
    }
}
