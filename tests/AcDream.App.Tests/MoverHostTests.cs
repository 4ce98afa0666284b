using System.Globalization;
using System.Numerics;
using System.Xml.Linq;
using AcDream.App.Fixtures;
using AcDream.App.Movement;
using AcDream.App.Scenes;
using AcDream.App.World;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.App.Tests;

/// <summary>The default Holtburg walk, run once for the tests that read it.</summary>
public sealed class DefaultWalk
{
    public DefaultWalk()
    {
        Scene scene = SceneReader.ReadDefault();
        World = scene.CreateWorld();
        Record = SceneRunner.Run(scene, World);
        Summary = WalkReport.Format(Record, "walk.svg");
    }

    internal HoltburgWorld World { get; }

    internal WalkRecord Record { get; }

    internal string Summary { get; }

    internal LegResult Leg(string start) => Record.Legs.Single(l => l.Leg.Name.StartsWith(start, StringComparison.Ordinal));

    internal FrameSample[] Frames(LegResult leg) => [.. Record.Samples.Where(s => s.Frame >= leg.FirstFrame && s.Frame <= leg.LastFrame)];
}

/// <summary>Movers on the host side: the window keeps them with their landblocks, the player and the creatures walk among them, the door opens, holds and closes.</summary>
public sealed class MoverHostTests(DefaultWalk walk) : IClassFixture<DefaultWalk>
{
    private const uint Holtburg = HoltburgWorld.Holtburg;
    private const uint Door = ObjectPlacements.CottageWestDoor;
    private const uint Standing = SceneRunner.FirstCreatureId; // the creature standing on the run to the west door
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";
    private static readonly float Radius = MoverBody.Player.Radius;

    // The west door's slab, landblock-local (= world here), worked out by hand from cell 0xA9B40145's portal to the
    // outdoors (x 136.3, y 4.2..6.1, z 94..96.5) and the slab's −0.009..0.252 m across its own frame, whose +Y points east.
    private const float SlabWest = 136.291f, SlabEast = 136.552f, SlabSouth = 4.2f, SlabNorth = 6.1f;

    /// <summary>How far a point is from the slab's footprint, seen from above (0 inside it).</summary>
    private static float FromSlab(Vector3 p)
    {
        float dx = MathF.Max(0f, MathF.Max(SlabWest - p.X, p.X - SlabEast)), dy = MathF.Max(0f, MathF.Max(SlabSouth - p.Y, p.Y - SlabNorth));
        return MathF.Sqrt((dx * dx) + (dy * dy));
    }

    [Fact]
    public void CottageWestDoor_IsASlabOfTheGameDoorsThicknessInTheDoorwayOf0x0145()
    {
        WorldDoor door = new HoltburgWorld().Doors["cottage-west"];
        Vector3[] corners = [.. door.Slab.VertexArray.Vertices.Values.Select(v => door.Position + Vector3.Transform(v.Origin, door.Orientation))];

        (door.Id, door.CellId, door.Slab.Id).Should().Be((0x7A9B4145u, 0xA9B40145u, 0x01FFF145u));
        door.Slab.PhysicsPolygons.Should().HaveCount(6, "a closed box");
        corners.Should().HaveCount(8);
        var lo = new Vector3(corners.Min(c => c.X), corners.Min(c => c.Y), corners.Min(c => c.Z));
        var hi = new Vector3(corners.Max(c => c.X), corners.Max(c => c.Y), corners.Max(c => c.Z));
        Vector3.Distance(lo, new Vector3(SlabWest, SlabSouth, 94f)).Should().BeLessThan(1e-4f, $"the slab's low corner, got {lo}");
        Vector3.Distance(hi, new Vector3(SlabEast, SlabNorth, 96.5f)).Should().BeLessThan(1e-4f, $"the slab's high corner, got {hi}");
        Vector3.Distance(door.Position, new Vector3(136.3f, 5.15f, 94f)).Should().BeLessThan(1e-4f, $"its origin: the portal's bottom middle, got {door.Position}");
        Vector3.Transform(Vector3.UnitY, door.Orientation).Should().Match<Vector3>(y => Vector3.Distance(y, Vector3.UnitX) < 1e-5f, "its own +Y points into the door cell, east");
        door.Shape.Reach.Should().BeApproximately(MathF.Sqrt((0.95f * 0.95f) + (0.252f * 0.252f)), 1e-4f, "its walls reach a corner of the slab from its origin");
    }

    [Fact]
    public void DefaultScene_Creatures_NeverEndInsideEachOtherThePlayerOrAWall()
    {
        WalkRecord record = walk.Record;
        IReadOnlyList<CreaturePath> creatures = record.Creatures;
        int frames = record.Final.Frame;
        creatures.Should().HaveCount(21);
        creatures.Count(c => c.Creature.Wander > 0f).Should().Be(20, "20 wander, one stands");
        creatures.Select(c => c.Id).Should().Equal(Enumerable.Range(0, 21).Select(i => SceneRunner.FirstCreatureId + (uint)i));
        creatures.Should().OnlyContain(c => c.Samples.Count == frames + 1 && c.Removed.Count == 0, "every creature is in the world every frame (their landblock stays loaded)");

        // Each frame, every two creatures (and each creature and the player) whose heights overlap: their centres at
        // least two radii apart, seen from above, within 1 mm.
        var byFrame = new Vector3[frames + 1][];
        for (int f = 0; f <= frames; f++)
        {
            byFrame[f] = [.. creatures.Select(c => c.Samples[f].Position)];
            creatures.Should().OnlyContain(c => c.Samples[f].Frame == f);
        }

        int touching = 0;
        float closest = float.PositiveInfinity;
        for (int f = 0; f <= frames; f++)
        {
            Vector3[] at = byFrame[f];
            Vector3 player = record.Samples[f].Position;
            for (int i = 0; i < at.Length; i++)
            {
                for (int j = i + 1; j <= at.Length; j++)
                {
                    Vector3 other = j < at.Length ? at[j] : player;
                    if (MathF.Abs(at[i].Z - other.Z) >= MoverBody.Player.Height)
                    {
                        continue;
                    }

                    float d = Vector2.Distance(new Vector2(at[i].X, at[i].Y), new Vector2(other.X, other.Y));
                    d.Should().BeGreaterThanOrEqualTo((2f * Radius) - 1e-3f,
                        $"frame {f}: creature 0x{creatures[i].Id:X8} at {at[i]} and {(j < at.Length ? $"creature 0x{creatures[j].Id:X8}" : "the player")} at {other}");
                    closest = MathF.Min(closest, d);
                    touching += d < (2f * Radius) + 0.01f ? 1 : 0;
                }
            }
        }

        touching.Should().BeGreaterThan(100, $"the creatures walk into each other (closest {closest:F5} m), so the check above has contacts to judge");

        // Every creature stays outdoors, and its centre at least its radius from every upright wall of the objects
        // (the cottage's shell, the plinth) that reaches between its step height and its head.
        var walls = walk.World.ObjectSurfaces.SelectMany(o => o.GetWalls().Where(w => w.Radius == 0f).Select(w => (o.ObjectId, w.Outline)))
            .Where(w => MathF.Abs(Normal(w.Outline).Z) < 0.2f).ToList();
        walls.Should().HaveCountGreaterThan(20);
        var nearest = new List<string>();
        foreach (CreaturePath creature in creatures)
        {
            float best = float.PositiveInfinity;
            foreach (CreatureSample s in creature.Samples)
            {
                CellIds.IsIndoor(s.CellId).Should().BeFalse($"creature 0x{creature.Id:X8} frame {s.Frame} at {s.Position} in 0x{s.CellId:X8}");
                var p = new Vector2(s.Position.X, s.Position.Y);
                foreach ((uint objectId, Vector3[] outline) in walls)
                {
                    if (outline.Min(v => v.Z) >= s.Position.Z + MoverBody.Player.Height || outline.Max(v => v.Z) <= s.Position.Z + PlayerMovementMode.StepUpHeight)
                    {
                        continue;
                    }

                    for (int k = 0; k < outline.Length; k++)
                    {
                        Vector3 a = outline[k], b = outline[(k + 1) % outline.Length];
                        float d = SegmentDistance(p, new Vector2(a.X, a.Y), new Vector2(b.X, b.Y));
                        d.Should().BeGreaterThanOrEqualTo(Radius - 1e-3f, $"creature 0x{creature.Id:X8} frame {s.Frame} at {s.Position}: a wall of object 0x{objectId:X8} from {a} to {b}");
                        best = MathF.Min(best, d);
                    }
                }
            }

            nearest.Add(string.Create(CultureInfo.InvariantCulture, $"0x{creature.Id:X8}: {best:F4}"));
        }

        nearest.Count(n => float.Parse(n.Split(": ")[1], CultureInfo.InvariantCulture) < Radius + 0.01f)
            .Should().BeGreaterThanOrEqualTo(4, $"creatures reach the shell's east wall and the plinth's side, so the wall check has contacts to judge: {string.Join(", ", nearest)}");
        walk.Summary.Should().Contain(string.Create(CultureInfo.InvariantCulture, $"Closest centres: two creatures {record.ClosestCreatures().Distance:F3} m apart"));
    }

    [Fact]
    public void DefaultScene_Player_SlidesRoundTheCreatureStandingOnTheRunToTheWestDoor()
    {
        LegResult leg = walk.Leg("to the cottage's west door");
        CreaturePath standing = walk.Record.Creatures[0];
        Vector3 creature = standing.Samples[0].Position;
        (standing.Id, standing.Creature.Wander).Should().Be((Standing, 0f));
        standing.Samples.Should().OnlyContain(s => s.Position == creature, "it stands where it appeared");

        MoverTouch[] touched = [.. walk.Record.Touches.Where(t => t.MoverId == Standing)];
        touched.Should().HaveCountGreaterThan(5, "the player slides round it over several frames")
            .And.OnlyContain(t => t.Frame >= leg.FirstFrame && t.Frame <= leg.LastFrame && t.Stopped, $"on the run to the west door, frames {leg.FirstFrame}-{leg.LastFrame}");
        foreach (MoverTouch touch in touched)
        {
            FrameSample s = walk.Record.Samples[touch.Frame];
            Vector2 away = new Vector2(s.Position.X, s.Position.Y) - new Vector2(creature.X, creature.Y);
            away.Length().Should().BeInRange((2f * Radius) - 1e-3f, (2f * Radius) + 0.01f, $"frame {touch.Frame}: the player's body against the creature's, at {s.Position}");
            s.Slide.Should().NotBeNull($"frame {touch.Frame} slid");
            var normal = new Vector2(s.Slide!.Value.X, s.Slide.Value.Y);
            Vector2.Dot(normal, Vector2.Normalize(away)).Should().BeGreaterThan(0.99f, $"frame {touch.Frame}: the slide's normal {normal} (at the contact, part way through the frame) points from the creature towards the player, now {Vector2.Normalize(away)} from it");
        }

        leg.Reached.Should().BeTrue("round the creature the player goes on to the door");
        string[] lines = walk.Summary.Split(System.Environment.NewLine);
        lines.Should().ContainSingle(l => l.StartsWith("   4. to the cottage's west door", StringComparison.Ordinal))
            .Which.Should().EndWith($"; movers met: 0x{Standing:X8} creature ({touched.Length} frames)", walk.Summary);
        lines.Should().ContainSingle(l => l.StartsWith("Movers met: ", StringComparison.Ordinal))
            .Which.Should().Contain($"0x{Standing:X8} creature: {touched.Length} frames ({touched.Length} × stopped or slid the player), frames {touched[0].Frame}-{touched[^1].Frame}, leg 4;");
    }

    [Fact]
    public void DefaultScene_WestDoor_OpensThenWaitsClosingWhileThePlayerStandsInItThenCloses()
    {
        DoorChange[] changes = [.. walk.Record.DoorChanges];
        string all = string.Join(", ", changes.Select(c => $"{c.State}@{c.Frame}"));
        changes.Should().OnlyContain(c => c.DoorId == Door, all);
        changes.Select(c => c.State).Should().Equal([DoorState.Closed, DoorState.Open, DoorState.Closing, DoorState.Closed, DoorState.Open, DoorState.Closed], all);
        changes[0].Frame.Should().Be(0, "registered closed with its landblock");
        changes[1].Frame.Should().Be(walk.Leg("open the west door").FirstFrame, "opened on the leg's first frame");
        changes[2].Frame.Should().Be(walk.Leg("close the door behind").FirstFrame, "told to close on the leg's first frame, with the player in the doorway");

        // Closing while the player's body (where the frame's commit saw it: after the frame before) overlaps the slab;
        // closed at the first commit after it stands clear.
        for (int f = changes[2].Frame; f < changes[3].Frame; f++)
        {
            Vector3 p = walk.Record.Samples[f - 1].Position;
            FromSlab(p).Should().BeLessThan(Radius, $"frame {f}: the door waits, the player at {p} is in it");
        }

        (changes[3].Frame - changes[2].Frame).Should().BeGreaterThan(30, "held the second the player stood in the doorway, and while it walked out of it");
        Vector3 clear = walk.Record.Samples[changes[3].Frame - 1].Position;
        FromSlab(clear).Should().BeGreaterThanOrEqualTo(Radius, $"frame {changes[3].Frame}: closed once the player at {clear} stands clear");
        changes[3].Frame.Should().BeInRange(walk.Leg("in through the west door 0x0145").FirstFrame, walk.Leg("in through the west door 0x0145").LastFrame, "it closes behind the player walking in");

        // Open, the player passed through it (touched, not stopped); the second opening lets the player out and in again.
        walk.Record.Samples.Where(s => s.Frame > changes[1].Frame && s.Frame < changes[3].Frame).Should().Contain(s => s.CellId == 0xA9B40145u, "through its doorway");
        walk.Record.Touches.Where(t => t.MoverId == Door && ((t.Frame >= changes[1].Frame && t.Frame < changes[3].Frame) || (t.Frame >= changes[4].Frame && t.Frame < changes[5].Frame)))
            .Should().NotBeEmpty().And.OnlyContain(t => !t.Stopped, "an open door is only touched");
        walk.Summary.Split(System.Environment.NewLine).Should().ContainSingle(l => l.StartsWith("Door 0x7A9B4145 cottage west door: ", StringComparison.Ordinal)).Which.Should().Be(
            $"Door 0x7A9B4145 cottage west door: closed at frame 0; open at frame {changes[1].Frame} (leg 5); closing at frame {changes[2].Frame} (leg 6), held {changes[3].Frame - changes[2].Frame} frames; closed at frame {changes[3].Frame} (leg 7); open at frame {changes[4].Frame} (leg 23); closed at frame {changes[5].Frame} (leg 27).",
            walk.Summary);
    }

    [Fact]
    public void DefaultScene_ClosedWestDoor_StopsThePlayerFromInsideAndFromOutside()
    {
        foreach ((string name, bool inside) in new[] { ("back west at the closed door", true), ("east at the closed door", false) })
        {
            LegResult leg = walk.Leg(name);
            FrameSample[] frames = walk.Frames(leg);
            foreach (FrameSample s in frames)
            {
                if (inside)
                {
                    s.Position.X.Should().BeGreaterThanOrEqualTo(SlabEast + Radius - 1e-3f, $"{name}, frame {s.Frame}: at {s.Position}, the body stays east of the slab");
                    s.CellId.Should().Be(0xA9B40143u, $"{name}, frame {s.Frame}");
                }
                else
                {
                    s.Position.X.Should().BeLessThanOrEqualTo(SlabWest - Radius + 1e-3f, $"{name}, frame {s.Frame}: at {s.Position}, the body stays west of the slab");
                    CellIds.IsIndoor(s.CellId).Should().BeFalse($"{name}, frame {s.Frame}: 0x{s.CellId:X8}");
                }
            }

            leg.Reached.Should().BeFalse($"{name}: its point is beyond the door");
            MoverTouch[] stopped = [.. walk.Record.Touches.Where(t => t.MoverId == Door && t.Stopped && t.Frame >= leg.FirstFrame && t.Frame <= leg.LastFrame)];
            stopped.Length.Should().BeGreaterThan(15, $"{name}: the door stops the player frame after frame");
            MathF.Abs(frames[^1].Position.X - (inside ? SlabEast + Radius : SlabWest - Radius)).Should().BeLessThan(0.01f, $"{name}: it ends against the slab, at {frames[^1].Position}");
        }
    }

    [Theory]
    [InlineData(2f, 0f)]
    [InlineData(4f, 30f)]
    [InlineData(4f, -30f)]
    [InlineData(50f, 0f)]
    [InlineData(50f, 20f)]
    public void ClosedDoor_StopsABodyFromBothSides_OpenDoorLetsItThrough(float speed, float angle)
    {
        var world = new HoltburgWorld(HoltburgWorld.Worlds.Holtburg, ["cottage"]);
        WorldDoor door = world.Doors["cottage-west"];
        using var window = new GameWindow(world, world.HeightTable, Holtburg);
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out string? error).Should().BeTrue($"error: {error}");
        window.AddMover(door.Id, door.Shape, door.Position, door.CellId, door.Orientation, MoverState.Door);
        window.CommitMovers();

        foreach (bool open in new[] { false, true })
        {
            foreach (bool inside in new[] { false, true })
            {
                var start = new Vector3(inside ? 138.5f : 134.1f, 5.15f, 94f);
                float heading = (inside ? 270f : 90f) + angle;
                var mode = new PlayerMovementMode(window.Physics, start, inside ? 0xA9B40143u : 0xA9B40001u, heading * MathF.PI / 180f, MovementOptions.Player) { RunMetresPerSecond = speed };
                string what = $"{(open ? "open" : "closed")} door, from {(inside ? "inside" : "outside")} at {speed} m/s, {angle}° off its normal";
                for (int f = 0; f < 45; f++)
                {
                    mode.Update(new MovementIntent(1f, 0f, 0f, Run: true), 1f / 30f);
                    if (!open)
                    {
                        // Never into the slab; never indoors from outside (the door cell 0x0145 is the only way in), never
                        // out from inside. Beside the slab the body slides along it, and along the shell or the room's walls.
                        FromSlab(mode.Position).Should().BeGreaterThanOrEqualTo(Radius - 1e-3f, $"{what}: frame {f} at {mode.Position} in 0x{mode.CellId:X8}, the body stays off the slab");
                        CellIds.IsIndoor(mode.CellId).Should().Be(inside, $"{what}: frame {f} at {mode.Position} in 0x{mode.CellId:X8}, the body stays on its side");
                        if (inside)
                        {
                            mode.Position.X.Should().BeGreaterThan(SlabEast, $"{what}: frame {f}, east of the door");
                        }
                    }
                }

                if (open && angle == 0f)
                {
                    (inside ? mode.Position.X < SlabWest - Radius : mode.Position.X > SlabEast + Radius).Should().BeTrue($"{what}: it walked through, to {mode.Position} in 0x{mode.CellId:X8}");
                }
            }

            window.Physics.Movers.Open(door.Id);
            window.CommitMovers();
        }
    }

    [Fact]
    public void AddMover_InALandblockNotLoaded_IsRefusedNamingIt()
    {
        var world = new HoltburgWorld();
        using var window = new GameWindow(world, world.HeightTable, Holtburg);
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out _).Should().BeTrue();

        Action add = () => window.AddMover(1u, MoverShape.Cylinder(0.48f, 1.835f), new Vector3(-10f, 50f, 94f), 0xA8B40030u, Quaternion.Identity, MoverState.Creature);

        add.Should().Throw<InvalidOperationException>().WithMessage("*0xA8B40030*0xA8B4FFFF*not loaded*");
        window.Physics.Movers.Count.Should().Be(0);
    }

    [Fact]
    public void UnloadLandblock_RemovesItsMoversAndOnlyThem()
    {
        var world = new HoltburgWorld();
        using var window = new GameWindow(world, world.HeightTable, Holtburg);
        const uint east = 0xAAB4FFFFu;
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out _).Should().BeTrue();
        window.ApplyLoadedTerrainLocked(east, world.Load(east), out _).Should().BeTrue();
        MoverShape cylinder = MoverShape.Cylinder(0.48f, 1.835f);
        var here = new Vector3(150f, 30f, 94f); // in 0xA9B4's outdoor cell (6, 1)
        window.AddMover(1u, cylinder, here, 0xA9B40032u, Quaternion.Identity, MoverState.Creature);
        window.AddMover(2u, cylinder, new Vector3(250f, 30f, 94f), 0xAAB40012u, Quaternion.Identity, MoverState.Creature);
        window.CommitMovers();
        ResolveResult blocked = window.Physics.Resolve(here - new Vector3(2f, 0f, 0f), 0xA9B40032u, new Vector3(2f, 0f, 0f), 0.6f, MovementOptions.Player, 0u, stackalloc uint[4], out int count, out MoveReport met);
        (met.Wall.Kind, met.Wall.Id).Should().Be((SurfaceKind.Mover, 1u), $"mover 1 stops the body, at {blocked.Position}");

        window.UnloadLandblockLocked(Holtburg);
        window.CommitMovers();

        window.Physics.Movers.Count.Should().Be(1, "mover 1 left with 0xA9B4; mover 2 stands in 0xAAB4");
        window.Physics.Movers.GetState(2u).Should().Be(MoverState.Creature);
        FluentActions.Invoking(() => window.Physics.Movers.GetState(1u)).Should().Throw<ArgumentException>("mover 1 is gone");
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out _).Should().BeTrue();
        ResolveResult through = window.Physics.Resolve(here - new Vector3(2f, 0f, 0f), 0xA9B40032u, new Vector3(4f, 0f, 0f), 0.6f, MovementOptions.Player, 0u, stackalloc uint[4], out count, out met);
        through.Position.X.Should().BeApproximately(here.X + 2f, 1e-3f, $"nothing stands there after the reload ({through.Outcome}, {met.Wall})");
        count.Should().Be(0);
    }

    [Fact]
    public void SceneRunner_CreatureOfALandblockThatUnloads_LeavesWithIt()
    {
        Scene scene = SceneReader.Parse("""
            { "name": "leave", "start": { "position": [-24, 56], "heading": 90 }, "effects": "player",
              "creatures": [ { "at": [-200, 60], "wander": 2, "seed": 9 }, { "at": [30, 60], "wander": 2 } ],
              "legs": [ { "name": "east across the seam", "to": [40, 56], "run": true } ] }
            """, "test");

        WalkRecord record = SceneRunner.Run(scene);

        StreamingEvent unload = record.Streaming.Single(e => !e.Loaded && e.LandblockId == 0xA7B4FFFFu);
        CreaturePath gone = record.Creatures[0], staying = record.Creatures[1];
        gone.Removed.Should().Equal([(unload.Frame, 0xA7B4FFFFu)], "its landblock 0xA7B4 unloads as the player crosses into 0xA9B4");
        gone.Samples[^1].Frame.Should().Be(unload.Frame - 1, "it walked until its landblock left");
        gone.Samples.Select(s => s.Frame).Should().Equal(Enumerable.Range(0, unload.Frame));
        staying.Removed.Should().BeEmpty();
        staying.Samples.Should().HaveCount(record.Final.Frame + 1);
        WalkReport.Format(record, "x.svg").Should().Contain($"Creature 0x{SceneRunner.FirstCreatureId:X8} left with its landblock 0xA7B4 at frame {unload.Frame}.");
    }

    [Fact]
    public void MovingThePlayerAndTwentyCreatures_AllocatesNothingPerFrame()
    {
        var world = new HoltburgWorld(HoltburgWorld.Worlds.Holtburg, ["cottage"]);
        WorldDoor door = world.Doors["cottage-west"];
        using var window = new GameWindow(world, world.HeightTable, Holtburg);
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out _).Should().BeTrue();
        PhysicsEngine engine = window.Physics;
        MoverShape cylinder = MoverShape.Cylinder(MoverBody.Player.Radius, MoverBody.Player.Height);
        window.AddMover(door.Id, door.Shape, door.Position, door.CellId, door.Orientation, MoverState.Door);
        var player = new PlayerMovementMode(engine, new Vector3(134f, 5.15f, 94f), 0xA9B40001u, MathF.PI / 2f, MovementOptions.Player) { MoverId = SceneRunner.PlayerId };
        window.AddMover(SceneRunner.PlayerId, cylinder, player.Position, player.CellId, Quaternion.Identity, MoverState.Player);
        var creatures = new List<Creature>();
        for (int i = 0; i < 20; i++)
        {
            var home = new Vector3(100f + (6f * (i % 5)), 30f + (6f * (i / 5)), 94f); // on the flat ground north-west of the cottage, in 0xA9B4
            var creature = new Creature(SceneRunner.FirstCreatureId + (uint)i, new SceneCreature(new Vector2(home.X, home.Y), 2f, i + 1));
            creature.Appear(new PlayerMovementMode(engine, home, 0xA9B40001u, 0f, MovementOptions.Player) { MoverId = creature.Id }, 0);
            window.AddMover(creature.Id, cylinder, home, creature.Mode!.CellId, Quaternion.Identity, MoverState.Creature);
            creatures.Add(creature);
        }

        float walked = 0f;
        void Frame()
        {
            window.CommitMovers();
            player.Update(new MovementIntent(1f, 0f, 0.2f, Run: false), 1f / 30f);
            window.MoveMover(SceneRunner.PlayerId, player.Position, player.CellId, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, -player.Heading));
            foreach (Creature creature in creatures)
            {
                Vector3 from = creature.Mode!.Position;
                creature.Step(1f / 30f);
                walked += Vector3.Distance(from, creature.Mode.Position);
                window.MoveMover(creature.Id, creature.Mode.Position, creature.Mode.CellId, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, -creature.Mode.Heading));
            }
        }

        for (int f = 0; f < 60; f++)
        {
            Frame(); // warm up: the commits' spare states, the JIT
        }

        // A call with a mover near it on this thread: the thread's one record of the movers a call reads is made once.
        Vector3 beside = creatures[0].Mode!.Position + new Vector3(1.0f, 0f, 0f); // (its walls 0.52 m away, within the call's reach)
        engine.Resolve(beside, creatures[0].Mode!.CellId, new Vector3(-0.1f, 0f, 0f), 0.6f, MovementOptions.Player);

        // Three windows of 100 frames: a cost per frame shows in every window; a one-off of the runtime (a type first
        // touched, code compiled again at a higher tier while other tests run beside this one) in one at most.
        walked = 0f;
        long[] windows = new long[3];
        for (int w = 0; w < windows.Length; w++)
        {
            long start = GC.GetAllocatedBytesForCurrentThread();
            for (int f = 0; f < 100; f++)
            {
                Frame();
            }

            windows[w] = GC.GetAllocatedBytesForCurrentThread() - start;
        }

        windows.Count(bytes => bytes == 0).Should().BeGreaterThanOrEqualTo(
            2, $"moving and committing 22 movers and resolving 21 of them allocates nothing per frame (bytes in each window of 100 frames: {string.Join(", ", windows)})");
        walked.Should().BeGreaterThan(100f, "the creatures walked meanwhile (2 m/s, three intents in four)");
        engine.Movers.Count.Should().Be(22);
    }

    [Fact]
    public void WalkSvg_DrawsEachCreaturesPathAndBodyAndTheDoorsSlab()
    {
        XDocument svg = WalkSvg.Build(walk.Record, walk.World);

        XElement[] groups = [.. svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "creatures").Elements(Svg + "g")];
        groups.Select(g => (string?)g.Attribute("data-mover-id")).Should().Equal(walk.Record.Creatures.Select(c => $"0x{c.Id:X8}"));

        // The map is x' = a + s·x, y' = b − s·y: fit it on two creatures' bodies, then every body is drawn where its
        // creature ended, at the body's radius, and every path starts where its creature appeared and ends where it ended.
        Vector2 Centre(XElement g) => new(Number(Body(g), "cx"), Number(Body(g), "cy"));
        Vector3 e0 = walk.Record.Creatures[0].Samples[^1].Position, e1 = walk.Record.Creatures[12].Samples[^1].Position;
        float scale = (Centre(groups[12]).X - Centre(groups[0]).X) / (e1.X - e0.X);
        float a = Centre(groups[0]).X - (scale * e0.X), b = Centre(groups[0]).Y + (scale * e0.Y);
        Vector2 Map(Vector3 p) => new(a + (scale * p.X), b - (scale * p.Y));
        for (int i = 0; i < groups.Length; i++)
        {
            CreaturePath creature = walk.Record.Creatures[i];
            Vector2.Distance(Centre(groups[i]), Map(creature.Samples[^1].Position)).Should().BeLessThan(0.05f, $"creature 0x{creature.Id:X8}'s body at its end {creature.Samples[^1].Position}");
            Number(Body(groups[i]), "r").Should().BeApproximately(Radius * scale, 0.01f, $"creature 0x{creature.Id:X8}: the body's radius at {scale} px per metre");
            XElement[] paths = [.. groups[i].Elements(Svg + "polyline")];
            if (creature.Creature.Wander == 0f)
            {
                paths.Should().BeEmpty($"creature 0x{creature.Id:X8} stands");
                continue;
            }

            paths.Should().ContainSingle($"creature 0x{creature.Id:X8} walked in one piece");
            Vector2[] points = Points((string)paths[0].Attribute("points")!);
            points.Length.Should().BeInRange(100, creature.Samples.Count, $"creature 0x{creature.Id:X8}: a point every {0.25f} m of its walk");
            Vector2.Distance(points[0], Map(creature.Samples[0].Position)).Should().BeLessThan(0.05f, $"creature 0x{creature.Id:X8}'s path starts at home");
            Vector2.Distance(points[^1], Map(creature.Samples[^1].Position)).Should().BeLessThan(0.05f, $"creature 0x{creature.Id:X8}'s path ends where it ended");
        }

        XElement door = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "doors").Elements(Svg + "g").Single();
        ((string?)door.Attribute("data-mover-id")).Should().Be("0x7A9B4145");
        Vector2[] corners = [.. door.Elements(Svg + "polygon").SelectMany(p => Points((string)p.Attribute("points")!))];
        corners.Should().HaveCount(24, "six faces of four corners");
        var lo = new Vector2(corners.Min(c => c.X), corners.Min(c => c.Y));
        var hi = new Vector2(corners.Max(c => c.X), corners.Max(c => c.Y));
        Vector2.Distance(lo, Map(new Vector3(SlabWest, SlabNorth, 0f))).Should().BeLessThan(0.05f, $"the slab's north-west corner, drawn at {lo}");
        Vector2.Distance(hi, Map(new Vector3(SlabEast, SlabSouth, 0f))).Should().BeLessThan(0.05f, $"the slab's south-east corner, drawn at {hi}");
        svg.Descendants(Svg + "text").Select(t => t.Value).Should().Contain(t => t.StartsWith("creatures (21): each one's path", StringComparison.Ordinal));

        static XElement Body(XElement group) => group.Elements(Svg + "circle").Single(c => (string?)c.Attribute("class") == "creature-body");
    }

    [Fact]
    public void DefaultScene_IsTheSameOnEveryRun_CreaturesDoorAndSummary()
    {
        WalkRecord again = SceneRunner.Run(SceneReader.ReadDefault());

        again.Samples.Should().Equal(walk.Record.Samples);
        for (int i = 0; i < again.Creatures.Count; i++)
        {
            again.Creatures[i].Samples.Should().Equal(walk.Record.Creatures[i].Samples, $"creature {i}");
        }

        again.DoorChanges.Should().Equal(walk.Record.DoorChanges);
        again.Touches.Should().Equal(walk.Record.Touches);
        WalkReport.Format(again, "walk.svg").Should().Be(walk.Summary);
    }

    [Theory]
    [InlineData("\"creatures\": \"many\",", "field creatures: must be an array of at most 256 creatures")]
    [InlineData("\"creatures\": [ { \"wander\": 2 } ],", "field creatures[0].at: is missing")]
    [InlineData("\"creatures\": [ { \"at\": [1, 2], \"wander\": -1 } ],", "field creatures[0].wander: must be between 0 and 50")]
    [InlineData("\"creatures\": [ { \"at\": [1, 2], \"seed\": 1.5 } ],", "field creatures[0].seed: must be a whole number")]
    [InlineData("\"creatures\": [ { \"at\": [1, 2], \"speed\": 3 } ],", "field creatures[0].speed: unknown field")]
    [InlineData("\"creatures\": [ { \"at\": [5000, 2] } ],", "field creatures[0].at: must be within 384 m")]
    [InlineData("\"doors\": [\"back\"],", "field doors[0]: must be one of the holtburg world's doors (\"cottage-west\")")]
    [InlineData("\"doors\": [\"cottage-west\", \"cottage-west\"],", "field doors[1]: is listed twice")]
    [InlineData("\"world\": \"staircase\", \"doors\": [\"cottage-west\"],", "field doors[0]: must be one of the staircase world's doors (it has none)")]
    public void SceneReader_BadCreaturesOrDoors_NameTheField(string field, string expected)
    {
        string json = $$"""{ "name": "x", {{field}} "start": { "position": [0, 0] }, "legs": [ { "name": "a", "to": [1, 0] } ] }""";
        Action read = () => SceneReader.Parse(json, "test");
        read.Should().Throw<SceneFormatException>().WithMessage($"*{expected}*");
    }

    [Theory]
    [InlineData("", "{ \"name\": \"a\", \"to\": [1, 0], \"open\": \"cottage-west\" }", "field legs[0].open: must name one of the scene's \"doors\" (it lists none)")]
    [InlineData("\"doors\": [\"cottage-west\"],", "{ \"name\": \"a\", \"forward\": 0, \"seconds\": 1, \"close\": \"front\" }", "field legs[0].close: must name one of the scene's \"doors\" (\"cottage-west\")")]
    [InlineData("\"doors\": [\"cottage-west\"],", "{ \"name\": \"a\", \"to\": [1, 0], \"open\": \"cottage-west\", \"close\": \"cottage-west\" }", "field legs[0]: has \"open\" and \"close\"")]
    public void SceneReader_BadDoorActions_NameTheField(string doors, string leg, string expected)
    {
        string json = $$"""{ "name": "x", {{doors}} "start": { "position": [0, 0] }, "legs": [ {{leg}} ] }""";
        Action read = () => SceneReader.Parse(json, "test");
        read.Should().Throw<SceneFormatException>().WithMessage($"*{expected}*");
    }

    [Fact]
    public void SceneReader_CreaturesDoorsAndDoorActions_AreRead()
    {
        Scene scene = SceneReader.Parse("""
            { "name": "x", "start": { "position": [0, 0] }, "doors": ["cottage-west"],
              "creatures": [ { "at": [1, 2] }, { "at": [3, 4], "wander": 2.5, "seed": 77 } ],
              "legs": [ { "name": "a", "to": [1, 0], "open": "cottage-west" }, { "name": "b", "turn": 1, "seconds": 1, "close": "cottage-west" } ] }
            """, "test");

        scene.Creatures.Should().Equal([new SceneCreature(new Vector2(1f, 2f), 0f, 1), new SceneCreature(new Vector2(3f, 4f), 2.5f, 77)], "the seed defaults to the creature's number");
        scene.Doors.Should().Equal(["cottage-west"]);
        (scene.Legs[0].Open, scene.Legs[0].Close, scene.Legs[1].Open, scene.Legs[1].Close).Should().Be(("cottage-west", null, null, "cottage-west"));
    }

    private static Vector3 Normal(Vector3[] loop)
    {
        Vector3 n = Vector3.Zero;
        for (int i = 0; i < loop.Length; i++)
        {
            n += Vector3.Cross(loop[i], loop[(i + 1) % loop.Length]);
        }

        return Vector3.Normalize(n);
    }

    private static float SegmentDistance(Vector2 p, Vector2 a, Vector2 b)
    {
        Vector2 ab = b - a;
        float t = ab.LengthSquared() > 0f ? Math.Clamp(Vector2.Dot(p - a, ab) / ab.LengthSquared(), 0f, 1f) : 0f;
        return Vector2.Distance(p, a + (ab * t));
    }

    private static float Number(XElement element, string attribute) => float.Parse((string)element.Attribute(attribute)!, CultureInfo.InvariantCulture);

    private static Vector2[] Points(string points) =>
        [.. points.Split(' ', StringSplitOptions.RemoveEmptyEntries)
            .Select(p => p.Split(','))
            .Select(xy => new Vector2(float.Parse(xy[0], CultureInfo.InvariantCulture), float.Parse(xy[1], CultureInfo.InvariantCulture)))];
}
