using System.Globalization;
using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.App.Movement;
using AcDream.App.Scenes;
using AcDream.App.World;
using AcDream.Core.Physics;
using static AcDream.App.Tests.CellGeometry;

namespace AcDream.App.Tests;

/// <summary>The pointer's ray: the default scene's five rays as the summary prints them, and the ray's rules.</summary>
public sealed class PointerTests(DefaultWalk walk) : IClassFixture<DefaultWalk>
{
    private const uint Holtburg = HoltburgWorld.Holtburg;
    private const uint Door = ObjectPlacements.CottageWestDoor;
    private const uint Standing = SceneRunner.FirstCreatureId;

    private PointerResult Ray(string start) => walk.Record.Pointers.Single(p => p.Pointer.Name.StartsWith(start, StringComparison.Ordinal));

    private static string Show(PointerResult p) => string.Create(CultureInfo.InvariantCulture, $"{p.Pointer.Name}: from {p.Pointer.From} towards {p.Pointer.Towards} after frame {p.Frame}: {p.Hit}");

    /// <summary>The point the ray from the pointer's start through its target reaches at Z = <paramref name="z"/>.</summary>
    private static Vector3 AtHeight(ScenePointer ray, float z) => ray.From + ((ray.Towards - ray.From) * ((ray.From.Z - z) / (ray.From.Z - ray.Towards.Z)));

    [Fact]
    public void DefaultWalk_FiveRaysAfterLeg24_HitWhatTheyAimAt()
    {
        walk.Record.Pointers.Should().HaveCount(5).And.OnlyContain(p => p.Pointer.AfterLeg == 24 && p.Frame == walk.Record.Legs[23].LastFrame, "all cast after leg 24");
        FrameSample player = walk.Record.Samples.Single(s => s.Frame == walk.Record.Legs[23].LastFrame);

        // The ground: flat at 94 m, reached past the player, whose body the ray goes through.
        PointerResult ground = Ray("the ground");
        (ground.Hit.Hit, ground.Hit.Kind, ground.Hit.Id, ground.Hit.CellId).Should().Be((true, SurfaceKind.Terrain, 0xA9B40029u, 0xA9B40029u), Show(ground));
        Vector3.Distance(ground.Hit.Point, AtHeight(ground.Pointer, 94f)).Should().BeLessThan(1e-3f, Show(ground));
        Vector3 p = AtHeight(ground.Pointer, player.Position.Z + 1f); // the ray one metre over the player's feet
        Vector2.Distance(new Vector2(p.X, p.Y), new Vector2(player.Position.X, player.Position.Y)).Should().BeLessThan(MoverBody.Player.Radius, $"the ray passes through the player's body (at {player.Position}), which it ignores: {Show(ground)}");

        // The north room 0x0141's floor (94 m, level with the terrain under the cottage) through the north doorway 0x014F's portal to the outdoors.
        PointerResult floor = Ray("the north room's floor");
        (floor.Hit.Hit, floor.Hit.Kind, floor.Hit.Id, floor.Hit.CellId).Should().Be((true, SurfaceKind.CellFloor, 0xA9B40141u, 0xA9B40141u), Show(floor));
        Vector3.Distance(floor.Hit.Point, AtHeight(floor.Pointer, 94f)).Should().BeLessThan(1e-3f, Show(floor));
        OutdoorPortals(walk.World).Where(d => d.CellId == 0xA9B4014Fu).Should().ContainSingle()
            .Which.Polygon.Should().Match<Testing.ReferenceBody.Vec3[]>(d => Crosses(V(floor.Pointer.From), V(floor.Hit.Point), d), "the ray goes in through the north doorway");

        // The shell: the point is on one of its walls, the first the ray meets.
        PointerResult shell = Ray("the cottage shell");
        (shell.Hit.Hit, shell.Hit.Kind, shell.Hit.Id).Should().Be((true, SurfaceKind.BuildingShell, ObjectPlacements.CottageShell), Show(shell));
        ObjectSurface cottage = walk.World.ObjectSurfaces.Single(o => o.ObjectId == ObjectPlacements.CottageShell);
        cottage.GetWalls().Min(w => Distance(V(shell.Hit.Point), [.. w.Outline.Select(V)])).Should().BeLessThan(1e-3, $"on a wall of the shell: {Show(shell)}");
        CellIds.IsIndoor(shell.Hit.CellId).Should().BeFalse(Show(shell));

        // The creature standing at (100.03, 9.37): the ray meets its cylinder (radius 0.48 m) where it enters it.
        PointerResult creature = Ray("the creature");
        (creature.Hit.Hit, creature.Hit.Kind, creature.Hit.Id).Should().Be((true, SurfaceKind.Mover, Standing), Show(creature));
        Vector3 feet = walk.Record.Creatures[0].Samples.Single(s => s.Frame == creature.Frame).Position;
        creature.Hit.Point.X.Should().BeApproximately(feet.X - MoverBody.Player.Radius, 1e-3f, $"the ray runs east along y = its home's; the creature stands at {feet}: {Show(creature)}");
        creature.Hit.Point.Z.Should().BeInRange(feet.Z, feet.Z + MoverBody.Player.Height, Show(creature));

        // The west door, open: its slab still stands in the doorway and the ray stops at its west face (x 136.291).
        PointerResult door = Ray("the open west door");
        walk.Record.DoorChanges.Last(c => c.DoorId == Door && c.Frame <= door.Frame).State.Should().Be(DoorState.Open, "leg 23 opened it");
        (door.Hit.Hit, door.Hit.Kind, door.Hit.Id).Should().Be((true, SurfaceKind.Mover, Door), Show(door));
        door.Hit.Point.X.Should().BeApproximately(136.291f, 1e-3f, Show(door));
    }

    [Fact]
    public void DefaultWalk_TheSummaryPrintsEachRayAsCast()
    {
        string[] lines = walk.Summary.Split(System.Environment.NewLine);
        lines.Should().ContainSingle(l => l == "Pointer rays (radius 0, at most 100 m, stopping at everything but the player):", walk.Summary);
        var expected = new Dictionary<string, string>
        {
            ["the ground"] = "terrain 0xA9B40029 at (133.70, 0.50, 94.00)",
            ["the north room's floor"] = "cell floor 0xA9B40141 (cottage, north room) at (139.40, 17.00, 94.00)",
            ["the cottage shell"] = "building shell 0x01000A2B (cottage shell) at (128.00, ",
            ["the creature"] = "mover 0x80000001 (creature) at (99.55, 9.37, 95.20)",
            ["the open west door"] = "mover 0x7A9B4145 (cottage west door) at (136.29, 5.15, 95.25)",
        };
        foreach ((string name, string met) in expected)
        {
            PointerResult ray = Ray(name);
            string line = lines.Single(l => l.StartsWith($"  {ray.Pointer.Name} (after leg 24, frame {ray.Frame}): ", StringComparison.Ordinal));
            line.Should().Contain(met, Show(ray));
            line.Should().EndWith(string.Create(CultureInfo.InvariantCulture, $"{ray.Hit.Distance:F2} m, in cell 0x{ray.Hit.CellId:X8}."), Show(ray));
        }
    }

    [Fact]
    public void Cast_PassesThePlayerOnly_StopsAtACreatureAndAtTheDoorOpenOrClosed_AndEndsAtAHundredMetres()
    {
        var world = new HoltburgWorld(HoltburgWorld.Worlds.Holtburg, ["cottage"]);
        WorldDoor door = world.Doors["cottage-west"];
        using var window = new GameWindow(world, world.HeightTable, Holtburg);
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out string? error).Should().BeTrue(error);
        MoverShape body = MoverShape.Cylinder(MoverBody.Player.Radius, MoverBody.Player.Height);
        window.AddMover(door.Id, door.Shape, door.Position, door.CellId, door.Orientation, MoverState.Door);
        window.AddMover(SceneRunner.PlayerId, body, new Vector3(120f, 5.15f, 94f), 0xA9B40029u, Quaternion.Identity, MoverState.Player);
        window.AddMover(Standing, body, new Vector3(125f, 5.15f, 94f), 0xA9B40029u, Quaternion.Identity, MoverState.Creature);
        window.CommitMovers();
        var pointer = new Pointer(window.Physics, SceneRunner.PlayerId);
        var blind = new Pointer(window.Physics);
        var eye = new Vector3(118f, 5.15f, 95f);

        PointerHit creature = pointer.Cast(eye, 0u, Vector3.UnitX);
        PointerHit player = blind.Cast(eye, 0u, Vector3.UnitX * 7f);
        window.Physics.Movers.Remove(Standing);
        window.CommitMovers();
        PointerHit closed = pointer.Cast(eye, 0u, Vector3.UnitX);
        window.Physics.Movers.Open(door.Id);
        window.CommitMovers();
        PointerHit open = pointer.Cast(eye, 0u, Vector3.UnitX);
        PointerHit sky = pointer.Cast(eye, 0u, new Vector3(0f, 0f, 2f));

        (creature.Hit, creature.Kind, creature.Id).Should().Be((true, SurfaceKind.Mover, Standing), $"the player's own body is passed: {creature}");
        creature.Point.X.Should().BeApproximately(125f - MoverBody.Player.Radius, 1e-3f, $"{creature}");
        creature.Distance.Should().BeApproximately(6.52f, 1e-3f, $"{creature}");
        (player.Hit, player.Kind, player.Id).Should().Be((true, SurfaceKind.Mover, SceneRunner.PlayerId), $"a pointer that ignores no one meets the player: {player}");
        (closed.Kind, closed.Id, open.Kind, open.Id).Should().Be((SurfaceKind.Mover, door.Id, SurfaceKind.Mover, door.Id), $"closed {closed}; open {open}: the slab stands in the doorway either way");
        closed.Point.X.Should().BeApproximately(136.291f, 1e-3f, $"{closed}");
        open.Point.Should().Be(closed.Point);
        (sky.Hit, sky.Kind, sky.Id).Should().Be((false, SurfaceKind.None, 0u), $"{sky}");
        sky.Distance.Should().Be(Pointer.MaxLength);
        sky.Point.Should().Be(eye + new Vector3(0f, 0f, Pointer.MaxLength));
        (pointer.Options, pointer.PlayerId).Should().Be((new CastOptions(0f, CastFilter.None), SceneRunner.PlayerId));
        FluentActions.Invoking(() => pointer.Cast(eye, 0u, Vector3.Zero)).Should().Throw<ArgumentException>().WithMessage("*direction*");
        FluentActions.Invoking(() => pointer.Cast(eye, 0u, new Vector3(float.NaN, 0f, 0f))).Should().Throw<ArgumentException>().WithMessage("*direction*");
    }
}
