using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// Bad object data is an <see cref="ArgumentException"/> naming the object and what is wrong, and changes nothing;
/// so is a building or object reaching past the seam reach, named by its index, id and rule.
/// </summary>
public class ObjectBadDataTests
{
    private const uint Id = 0x01000123;

    private const float GroundZ = 94f;

    private static readonly Frame Here = ObjectKit.At(new Vector3(50f, 50f, 10f), 0.3f);

    private static GfxObj Box() => ObjectKit.Gfx(
        Id,
        [new(0, 0, 0), new(1, 0, 0), new(1, 1, 0), new(0, 1, 0)],
        [new(0, 0, 0), new(1, 0, 0), new(1, 0, 1), new(0, 0, 1)]);

    private static void Throws(Action build, params string[] words)
    {
        ArgumentException e = build.Should().Throw<ArgumentException>().Which;
        foreach (string word in words)
        {
            e.Message.Should().Contain(word, $"the message names the object and what is wrong: \"{e.Message}\"");
        }
    }

    [Fact]
    public void A_polygon_with_two_vertices()
    {
        GfxObj g = Box();
        g.PhysicsPolygons[1].VertexIds.RemoveAt(3);
        g.PhysicsPolygons[1].VertexIds.RemoveAt(2);
        Throws(() => _ = new ObjectSurface(g, Here, 0), "0x01000123", "polygon 1", "2 vertices");
    }

    [Fact]
    public void An_unknown_vertex_id()
    {
        GfxObj g = Box();
        g.PhysicsPolygons[0].VertexIds[2] = 77;
        Throws(() => _ = new ObjectSurface(g, Here, 0), "0x01000123", "polygon 0", "77");
    }

    [Fact]
    public void A_negative_vertex_id()
    {
        GfxObj g = Box();
        g.PhysicsPolygons[0].VertexIds[2] = -1;
        Throws(() => _ = new ObjectSurface(g, Here, 0), "0x01000123", "-1");
    }

    [Theory]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    public void A_vertex_not_finite(float bad)
    {
        GfxObj g = Box();
        g.VertexArray.Vertices[5].Origin = new Vector3(1f, bad, 0f);
        Throws(() => _ = new ObjectSurface(g, Here, 0), "0x01000123", "vertex 5", "finite");
    }

    [Fact]
    public void A_vertex_placed_too_far()
    {
        GfxObj g = Box();
        g.VertexArray.Vertices[5].Origin = new Vector3(1f, 2e6f, 0f);
        Throws(() => _ = new ObjectSurface(g, Here, 0), "0x01000123", "vertex 5", "farther");
    }

    [Fact]
    public void A_zero_quaternion_or_a_frame_not_finite()
    {
        Throws(() => _ = new ObjectSurface(Box(), ObjectKit.At(Vector3.Zero, new Quaternion(0, 0, 0, 0)), 0), "0x01000123", "frame");
        Throws(() => _ = new ObjectSurface(Box(), ObjectKit.At(new Vector3(float.NaN, 0, 0), Quaternion.Identity), 0), "0x01000123", "frame");
        Throws(() => _ = new ObjectSurface(Box(), ObjectKit.At(Vector3.Zero, new Quaternion(0, float.NaN, 0, 1)), 0), "0x01000123", "frame");
        var stab = new Stab { Id = Id, Frame = ObjectKit.At(Vector3.Zero, new Quaternion(0, 0, 0, 0)) };
        Throws(
            () => ObjectSurface.FromLandblock(0x12340000, new LandBlockInfo { Objects = [stab] }, [], new Dictionary<uint, GfxObj> { [Id] = Box() }, RealObjects.NoSetups),
            "0x01000123", "frame");
    }

    [Fact]
    public void A_setup_part_missing_or_a_pose_of_the_wrong_length()
    {
        (Setup setup, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree();
        setup.Parts.Add(0x01000999);
        Throws(() => _ = new ObjectSurface(setup, parts, Here, 0), "0x02000001", "part 1", "0x01000999");

        (setup, parts) = ObjectKit.Tree();
        setup.PlacementFrames[Placement.Default] = new AnimationFrame { Frames = [new Frame(), new Frame()] };
        Throws(() => _ = new ObjectSurface(setup, parts, Here, 0), "0x02000001", "2 frames");

        (setup, parts) = ObjectKit.Tree();
        setup.DefaultScale = [Vector3.One, Vector3.One];
        Throws(() => _ = new ObjectSurface(setup, parts, Here, 0), "0x02000001", "scales");
    }

    [Theory]
    [InlineData(-0.4f, 5f)]
    [InlineData(0.4f, -1f)]
    [InlineData(float.NaN, 5f)]
    public void A_bad_cylinder(float radius, float height)
    {
        (Setup setup, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree(radius, height);
        Throws(() => _ = new ObjectSurface(setup, parts, Here, 0), "0x02000001", "cylinder 0");
    }

    [Fact]
    public void The_wrong_kind_of_id()
    {
        GfxObj g = Box();
        g.Id = 0x02000123;
        Throws(() => _ = new ObjectSurface(g, Here, 0), "0x02000123", "not a GfxObj");

        (Setup setup, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree();
        setup.Id = 0x01000005;
        Throws(() => _ = new ObjectSurface(setup, parts, Here, 0), "0x01000005", "not a Setup");

        var stab = new Stab { Id = 0x03000001, Frame = Here };
        Throws(() => ObjectSurface.FromLandblock(0x12340000, new LandBlockInfo { Objects = [stab] }, [], RealObjects.GfxObjs, RealObjects.NoSetups), "0x03000001", "not a GfxObj");

        stab.Id = 0x01000777; // the right kind, but not given
        Throws(() => ObjectSurface.FromLandblock(0x12340000, new LandBlockInfo { Objects = [stab] }, [], RealObjects.GfxObjs, RealObjects.NoSetups), "0x01000777", "not found");
    }

    [Fact]
    public void An_object_in_a_cell_that_is_not_registered_changes_nothing()
    {
        var engine = new PhysicsEngine(TestData.Holtburg);
        var stray = new ObjectSurface(Box(), Here, 0xA9B40999);
        stray.CellId.Should().Be(0xA9B40999u);
        Throws(
            () => engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(), [stray]),
            "0x01000123", "0xA9B40999", "not among the cells");
        engine.ContainsLandblock(TestData.Holtburg).Should().BeFalse("a refused landblock is not registered");
    }

    [Fact]
    public void A_building_door_cell_not_among_the_cells_changes_nothing()
    {
        var engine = new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(90f), []);
        BuildingInfo cottage = ObjectPlacements.Cottage();
        cottage.Portals.Add(new BuildingPortal { OtherCellId = 0x0999 });
        ObjectSurface shell = ObjectSurface.Building(TestData.Holtburg, cottage, RealObjects.GfxObjs, RealObjects.NoSetups);
        Throws(
            () => engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(), [shell]),
            "0x01000A2B", "door cell", "0xA9B40999");

        // Without the cells, every door is missing: the first is named.
        Throws(
            () => engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], [shell]),
            "0x01000A2B", "door cell", "0xA9B40145");
        engine.TryGetGround(new Vector3(100f, 100f, 95f), 0xA9B40000, out float z, out _).Should().BeTrue();
        z.Should().Be(90f, "the landblock registered before is still there, unchanged");
    }

    [Fact]
    public void A_door_that_is_not_an_indoor_cell()
    {
        BuildingInfo cottage = ObjectPlacements.Cottage();
        cottage.Portals.Add(new BuildingPortal { OtherCellId = 0x0005 });
        Throws(() => ObjectSurface.Building(TestData.Holtburg, cottage, RealObjects.GfxObjs, RealObjects.NoSetups), "0x01000A2B", "portal 4", "0x0005");
    }

    [Fact]
    public void More_outdoor_objects_than_the_limit_changes_nothing()
    {
        var engine = new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(90f), []);
        var box = new ObjectSurface(Box(), Here, 0);
        var many = Enumerable.Repeat(box, PhysicsConstants.MaxOutdoorObjects + 1).ToList();
        Throws(
            () => engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], many),
            "0xA9B4FFFF", $"{PhysicsConstants.MaxOutdoorObjects + 1} objects outdoors", $"at most {PhysicsConstants.MaxOutdoorObjects}");
        engine.TryGetGround(new Vector3(100f, 100f, 95f), 0xA9B40000, out float z, out _).Should().BeTrue();
        z.Should().Be(90f, "the landblock registered before is still there, unchanged");

        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], many.Take(PhysicsConstants.MaxOutdoorObjects).ToList());
        engine.ContainsLandblock(TestData.Holtburg).Should().BeTrue("exactly the limit is accepted");
    }

    [Fact]
    public void A_building_or_object_reaching_past_the_seam_reach_is_refused_by_name_and_a_dungeon_is_not()
    {
        var engine = new PhysicsEngine(Holtburg);
        CellSurface building = new CellBuilder(0xA9B40100u, new Vector3(190f, 100f, GroundZ))
            .Physics(Wall(0f, 0f, 30f, 0f, 0f, 4f))
            .Portal(0xFFFF, new Vector3(0.5f, 1f, 1f), new(0f, 0.5f, 0f), new(1f, 0.5f, 0f), new(1f, 0.5f, 2f), new(0f, 0.5f, 2f)).Build();
        Action add = () => engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), [building]);
        add.Should().Throw<ArgumentException>().WithMessage("*cell 0xA9B40100*24 m past*").And.ParamName.Should().Be("cells");
        engine.LandblockCount.Should().Be(0, "a refused landblock is not registered");

        // A dungeon's cell (no way to the outdoors) may reach anywhere: outdoor movers never meet it.
        CellSurface dungeon = new CellBuilder(0xA9B40100u, new Vector3(190f, 100f, GroundZ - 30f)).Physics(Wall(0f, 0f, 300f, 0f, 0f, 4f)).Build();
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), [dungeon]);
        engine.LandblockCount.Should().Be(1);

        var tree = ObjectKit.Tree(0.4f, 5f);
        Action far = () => engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), [],
            [new ObjectSurface(tree.Setup, tree.Parts, ObjectKit.At(new Vector3(-30f, 50f, GroundZ), 0f), 0)]);
        ObjectRefusedException refused = far.Should().Throw<ObjectRefusedException>().WithMessage("*object 0x02000001*").Which;
        (refused.ParamName, refused.ObjectIndex, refused.ObjectId, refused.Rule).Should().Be(("objects", 0, 0x02000001u, ObjectRule.ReachesPastSeam));
        engine.LandblockCount.Should().Be(1, "the landblock registered before stays");
    }

    [Fact]
    public void A_refused_object_is_named_by_its_index_id_and_rule_so_the_rest_can_be_registered()
    {
        var engine = new PhysicsEngine(Holtburg);
        var tree = ObjectKit.Tree(0.4f, 5f);
        ObjectSurface Tree(Vector3 at, uint cellId = 0) => new(tree.Setup, tree.Parts, ObjectKit.At(at, 0f), cellId);
        var objects = new List<ObjectSurface> { Tree(new(50f, 50f, GroundZ)), Tree(new(60f, 50f, GroundZ), 0xA9B40150u), Tree(new(-30f, 50f, GroundZ)), Tree(new(70f, 50f, GroundZ)) };
        var refusals = new List<(int Index, ObjectRule Rule)>();
        while (true)
        {
            try
            {
                engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), [], objects);
                break;
            }
            catch (ObjectRefusedException e)
            {
                e.ObjectId.Should().Be(objects[e.ObjectIndex].ObjectId, e.Message);
                refusals.Add((e.ObjectIndex, e.Rule));
                objects.RemoveAt(e.ObjectIndex);
            }
        }

        refusals.Should().Equal([(1, ObjectRule.CellNotGiven), (1, ObjectRule.ReachesPastSeam)], "the tree in a cell not given, then the one 30 m past the seam");
        objects.Should().HaveCount(2);
        engine.TryGetGround(engine.ToWorld(Holtburg, new Vector3(50f, 50f, GroundZ + 10f)), 0u, 0f, out _, out _, out uint onTree).Should().BeTrue();
        onTree.Should().Be(0u, "a tree's top is no floor, but the landblock and its two good trees are registered");
        engine.LandblockCount.Should().Be(1);
    }
}
