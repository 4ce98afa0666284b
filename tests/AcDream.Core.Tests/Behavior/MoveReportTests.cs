using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;
using Xunit.Abstractions;

using AcDream.Core.Tests.Robustness;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// What a move met (<see cref="MoveReport"/>): the floor the answer stands on and the wall, shell or cylinder
/// that stopped or slid it, named by kind and id, on the real Holtburg buildings and cells and a tree; and the
/// answer with the report is the answer without it, bit for bit.
/// </summary>
[Trait("Mutation", "ObjectQueries")]
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public sealed class MoveReportTests(ITestOutputHelper output)
{
    private const uint Outdoors = 0xA9B40000;
    private const uint Tree = 0x02000001;

    private static PhysicsEngine World(uint centre = 0)
    {
        var engine = centre == 0 ? new PhysicsEngine() : new PhysicsEngine(centre);
        (Setup tree, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree();
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), HoltburgCells.Surfaces(),
            [.. RealObjects.HoltburgBuildings(), new ObjectSurface(tree, parts, ObjectKit.At(new Vector3(100f, 100f, 94f), 0f), 0)]);
        return engine;
    }

    public static TheoryData<string, MovementOptions, uint> Movers => new()
    {
        { "point, global frame", default, 0u },
        { "player, global frame", MovementOptions.Player, 0u },
        { "point, centred frame", default, TestData.Holtburg },
        { "player, centred frame", MovementOptions.Player, TestData.Holtburg },
    };

    [Theory]
    [MemberData(nameof(Movers))]
    public void Walking_into_the_cottage_shell_names_the_shell(string mover, MovementOptions options, uint centre)
    {
        PhysicsEngine engine = World(centre);
        Vector3 start = engine.ToWorld(Outdoors, new Vector3(144.5f, 12f, 94f));
        ResolveResult r = engine.Resolve(start, Outdoors, new Vector3(-2f, -0.3f, 0f), 0.6f, in options, out MoveReport report);
        output.WriteLine($"{mover}: {r}; {report}");
        r.Outcome.Should().BeOneOf([ResolveOutcome.Wall, ResolveOutcome.OuterWall, ResolveOutcome.Slid], mover);
        report.Wall.Should().Be(new SurfaceContact(SurfaceKind.BuildingShell, ObjectPlacements.CottageShell, r.SurfaceNormal), mover);
        report.Wall.Normal.X.Should().BeGreaterThan(0.9f, "the shell's east wall faces east");
        report.Floor.Should().Be(new SurfaceContact(SurfaceKind.Terrain, r.CellId, Vector3.UnitZ), mover);
    }

    [Theory]
    [MemberData(nameof(Movers))]
    public void Walking_into_a_tree_names_its_cylinder(string mover, MovementOptions options, uint centre)
    {
        PhysicsEngine engine = World(centre);
        Vector3 start = engine.ToWorld(Outdoors, new Vector3(101.5f, 100.05f, 94f));
        ResolveResult r = engine.Resolve(start, Outdoors, new Vector3(-1.5f, 0f, 0f), 0.6f, in options, out MoveReport report);
        output.WriteLine($"{mover}: {r}; {report}");
        r.Outcome.Should().BeOneOf([ResolveOutcome.Wall, ResolveOutcome.Slid], mover);
        report.Wall.Kind.Should().Be(SurfaceKind.Cylinder, mover);
        report.Wall.Id.Should().Be(Tree, mover);
        report.Wall.Normal.Should().Be(r.SurfaceNormal);
    }

    [Fact]
    public void Standing_on_the_plinth_a_cell_floor_and_the_terrain_names_each_floor()
    {
        PhysicsEngine engine = World();
        Vector3 onTop = engine.ToWorld(Outdoors, new Vector3(156.25f, 35.41f, 96f));
        engine.TryGetGround(onTop, Outdoors, 0.5f, out float top, out _, out _).Should().BeTrue();
        ResolveResult plinth = engine.Resolve(onTop with { Z = top }, Outdoors, new Vector3(0.1f, 0f, 0f), 0.6f, MovementOptions.Player, out MoveReport onPlinth);
        output.WriteLine($"plinth: {plinth}; {onPlinth}");
        plinth.IsOnGround.Should().BeTrue();
        onPlinth.Floor.Kind.Should().Be(SurfaceKind.ObjectFloor);
        onPlinth.Floor.Id.Should().Be(ObjectPlacements.SmallBuilding);
        onPlinth.Wall.Should().Be(default(SurfaceContact));

        FloorTriangleInfo t = HoltburgCells.Surface(ObjectPlacements.CottageCellar).GetFloorTriangles()[0];
        Vector3 centroid = engine.ToWorld(Outdoors, (t.A + t.B + t.C) / 3f);
        ResolveResult inRoom = engine.Resolve(centroid, ObjectPlacements.CottageCellar, Vector3.Zero, 0.6f, default, out MoveReport inside);
        output.WriteLine($"cellar at {centroid}: {inRoom}; {inside}");
        inRoom.IsOnGround.Should().BeTrue();
        inside.Floor.Kind.Should().Be(SurfaceKind.CellFloor);
        inside.Floor.Id.Should().Be(ObjectPlacements.CottageCellar);
        inside.Floor.Normal.Z.Should().BeGreaterThan(0.99f);

        ResolveResult open = engine.Resolve(engine.ToWorld(Outdoors, new Vector3(60f, 60f, 94f)), Outdoors, new Vector3(0.2f, 0f, 0f), 0.6f, default, out MoveReport field);
        field.Floor.Should().Be(new SurfaceContact(SurfaceKind.Terrain, open.CellId, Vector3.UnitZ));
        field.Wall.Kind.Should().Be(SurfaceKind.None);
    }

    [Theory]
    [MemberData(nameof(Movers))]
    public void Walking_into_a_cellar_wall_names_the_cell(string mover, MovementOptions options, uint centre)
    {
        PhysicsEngine engine = World(centre);
        FloorTriangleInfo t = HoltburgCells.Surface(ObjectPlacements.CottageCellar).GetFloorTriangles()[0];
        Vector3 start = engine.ToWorld(Outdoors, (t.A + t.B + t.C) / 3f);
        var cells = HoltburgCells.Fixtures.Keys.ToHashSet();
        int named = 0;
        for (int k = 0; k < 8; k++)
        {
            float angle = k * MathF.PI / 4f;
            var delta = new Vector3(6f * MathF.Cos(angle), 6f * MathF.Sin(angle), 0f);
            ResolveResult r = engine.Resolve(start, ObjectPlacements.CottageCellar, delta, 0.6f, in options, out MoveReport report);
            engine.Resolve(start, ObjectPlacements.CottageCellar, delta, 0.6f, in options).Should().Be(r, $"{mover}, heading {k}: the same answer without the report");
            output.WriteLine($"{mover}, heading {k}: {r}; {report}");
            bool walled = r.Outcome is ResolveOutcome.Wall or ResolveOutcome.OuterWall || (r.Outcome == ResolveOutcome.Slid && r.SurfaceNormal.Z == 0f);
            if (!walled)
            {
                report.Wall.Should().Be(default(SurfaceContact), $"{mover}, heading {k}: {r}");
                continue;
            }

            named++;
            report.Wall.Kind.Should().Be(SurfaceKind.CellWall, $"{mover}, heading {k}: {r}");
            cells.Should().Contain(report.Wall.Id, $"{mover}, heading {k}: a wall of one of Holtburg's cells");
            report.Wall.Normal.Should().Be(r.SurfaceNormal);
        }

        named.Should().BeGreaterThanOrEqualTo(4, $"{mover}: 6 m moves out of the cellar meet its walls");
    }
    [Theory]
    [InlineData(0u)]
    [InlineData(TestData.Holtburg)]
    public void Walking_into_an_object_inside_a_cell_names_that_object(uint centre)
    {
        // A room with two objects in it, each one wall polygon: A across the path at x 20, B registered
        // after it in a far corner. The point mover meets A and is refused there.
        const uint room = 0xA9B40100u, a = 0x01000601u, b = 0x01000602u;
        var engine = centre == 0 ? new PhysicsEngine() : new PhysicsEngine(centre);
        CellSurface cell = new CellBuilder(room).Floor(10, 10, 30, 30, 50f).Build();
        ObjectSurface[] objects =
        [
            new(ObjectKit.Gfx(a, TestData.Wall(20f, 15f, 20f, 25f, 49f, 53f)), ObjectKit.At(Vector3.Zero, 0f), room),
            new(ObjectKit.Gfx(b, TestData.Wall(12f, 28f, 14f, 28f, 49f, 53f)), ObjectKit.At(Vector3.Zero, 0f), room),
        ];
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(40f), [cell], objects);
        Vector3 start = engine.ToWorld(room, new Vector3(18f, 20f, 50f));
        ResolveResult r = engine.Resolve(start, room, new Vector3(4f, 0f, 0f), 0.5f, default, out MoveReport report);
        output.WriteLine($"{r}; {report}");
        r.Outcome.Should().Be(ResolveOutcome.Wall);
        (r.Position, r.IsRefused).Should().Be((start, true), "the point mover is refused at a wall and stays");
        report.Wall.Should().Be(new SurfaceContact(SurfaceKind.ObjectWall, a, r.SurfaceNormal));
        report.Wall.Normal.X.Should().BeApproximately(-1f, 1e-6f, "A's wall faces the mover, west");

        ResolveResult clear = engine.Resolve(start, room, new Vector3(0f, -3f, 0f), 0.5f, default, out MoveReport none);
        clear.Outcome.Should().NotBe(ResolveOutcome.Wall, $"{clear}");
        none.Wall.Should().Be(default(SurfaceContact), "nothing was met");
    }
}
