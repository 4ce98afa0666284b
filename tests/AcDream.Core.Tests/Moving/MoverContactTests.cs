using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Moving;

/// <summary>
/// A body never ends more than 1 mm inside a creature or a closed door (distances in double precision, independent of the
/// engine), at speeds up to 50 m/s, with the creature moving between calls; the door blocks from both sides when closed,
/// passes when open, holds while occupied and blocks again after; movers across a seam and in a cell.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class MoverContactTests(ITestOutputHelper output)
{
    private const uint Landblock = MoverSmokeTests.Landblock, Outdoor = MoverSmokeTests.Outdoor;
    private const float Ground = MoverSmokeTests.Ground, Frame = 1f / 30f, Touch = 0.96f;
    private static readonly Vector2 Axis = MoverSmokeTests.Axis;

    public static TheoryData<string, float> Speeds() => new()
    {
        { "centred", 1f }, { "centred", 5f }, { "centred", 20f }, { "centred", 50f },
        { "global", 1f }, { "global", 5f }, { "global", 20f }, { "global", 50f },
    };

    private static PhysicsEngine Field(string frame) => MoverSmokeTests.Field(frame);

    private static Vector3 At(PhysicsEngine engine, Vector2 local) => engine.ToWorld(Landblock, new Vector3(local, Ground));

    [Theory]
    [MemberData(nameof(Speeds))]
    public void A_body_never_ends_inside_a_standing_creature_and_slides_round_it(string frame, float speed)
    {
        PhysicsEngine engine = Field(frame);
        Vector3 creature = At(engine, Axis);
        engine.Movers.Add(2, MoverKit.Human, creature, Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        double worst = double.MaxValue;
        int slid = 0, runs = 0;
        for (int d = 0; d < 16; d++)
        {
            double a = d * Math.PI / 8;
            var dir = new Vector2((float)Math.Cos(a), (float)Math.Sin(a));
            var side = new Vector2(-dir.Y, dir.X);
            foreach (float offset in new[] { 0f, 0.1f, 0.5f, 0.9f, -0.3f })
            {
                var at = new ResolveResult(At(engine, Axis - (dir * 4f) + (side * offset)), Outdoor, true);
                for (int i = 0; i < (int)(10f / (speed * Frame)) + 2; i++)
                {
                    at = engine.Resolve(at.Position, at.CellId, new Vector3(dir * speed * Frame, 0f), 0.6f, MovementOptions.Player);
                    double apart = MoverReference.Apart(at.Position, creature);
                    worst = Math.Min(worst, apart);
                    apart.Should().BeGreaterThanOrEqualTo(Touch - 0.001, $"direction {d}, offset {offset}, frame {i}: {at}");
                    slid += at.Outcome == ResolveOutcome.Slid ? 1 : 0;
                }

                runs++;
            }
        }

        output.WriteLine($"{runs} runs at {speed} m/s: nearest centre distance {worst:F6} m, {slid} slid frames");
        worst.Should().BeLessThan(Touch + 0.01, "the body reached the creature");
        slid.Should().BeGreaterThan(0, "off-centre runs slide round it");
    }

    [Theory]
    [MemberData(nameof(Speeds))]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_body_and_a_creature_walking_at_each_other_never_overlap(string frame, float speed)
    {
        // Both registered; each resolves its move with its own id (so it meets the other) and is moved and committed
        // before the other's call: the creature moves between the body's calls.
        PhysicsEngine engine = Field(frame);
        double worst = double.MaxValue;
        for (int d = 0; d < 8; d++)
        {
            double a = d * Math.PI / 4 + 0.1;
            var dir = new Vector2((float)Math.Cos(a), (float)Math.Sin(a));
            var side = new Vector2(-dir.Y, dir.X) * (0.2f * (d % 3));
            var body = new ResolveResult(At(engine, Axis - (dir * 3f)), Outdoor, true);
            var creature = new ResolveResult(At(engine, Axis + (dir * 3f) + side), Outdoor, true);
            engine.Movers.Add(1, MoverKit.Human, body.Position, Outdoor, Quaternion.Identity, MoverState.Player);
            engine.Movers.Add(2, MoverKit.Human, creature.Position, Outdoor, Quaternion.Identity, MoverState.Creature);
            engine.Movers.Commit();
            for (int i = 0; i < (int)(8f / (speed * Frame)) + 2; i++)
            {
                creature = engine.Resolve(creature.Position, creature.CellId, new Vector3(-dir * speed * Frame, 0f), 0.6f, MovementOptions.Player, 2u);
                engine.Movers.Move(2, creature.Position, creature.CellId, Quaternion.Identity);
                engine.Movers.Commit();
                MoverReference.Apart(body.Position, creature.Position).Should().BeGreaterThanOrEqualTo(Touch - 0.001, $"run {d}, frame {i}, creature: {creature}");
                body = engine.Resolve(body.Position, body.CellId, new Vector3(dir * speed * Frame, 0f), 0.6f, MovementOptions.Player, 1u);
                engine.Movers.Move(1, body.Position, body.CellId, Quaternion.Identity);
                engine.Movers.Commit();
                double apart = MoverReference.Apart(body.Position, creature.Position);
                worst = Math.Min(worst, apart);
                apart.Should().BeGreaterThanOrEqualTo(Touch - 0.001, $"run {d}, frame {i}, body: {body}");
            }

            engine.Movers.Remove(1).Should().BeTrue();
            engine.Movers.Remove(2).Should().BeTrue();
        }

        output.WriteLine($"{speed} m/s: nearest centre distance {worst:F6} m");
        worst.Should().BeLessThan(Touch + 0.01, "they met");
    }

    [Theory]
    [InlineData("centred", 0.0)]
    [InlineData("centred", 0.7)]
    [InlineData("global", 2.3)]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_closed_door_blocks_from_both_sides_passes_open_holds_while_occupied_and_blocks_again(string frame, double yaw)
    {
        PhysicsEngine engine = Field(frame);
        const float half = 0.6f;
        Vector3 hinge = At(engine, Axis);
        engine.Movers.Add(9, new MoverShape(MoverReference.SlabModel(2 * half, 2.2f)), hinge, Outdoor, MoverReference.Yaw(yaw), MoverState.Door);
        engine.Movers.Commit();
        var across = new Vector2((float)-Math.Sin(yaw), (float)Math.Cos(yaw)); // the slab's +Y, in the world
        double worst = double.MaxValue;

        ResolveResult Walk(Vector2 from, Vector2 dir, float speed, int frames)
        {
            var at = new ResolveResult(At(engine, from), Outdoor, true);
            for (int i = 0; i < frames; i++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(dir * speed * Frame, 0f), 0.6f, MovementOptions.Player);
                double gap = MoverReference.ToSlab(at.Position, hinge, yaw, half);
                if (engine.Movers.GetPendingDoorState(9) == DoorState.Closed)
                {
                    worst = Math.Min(worst, gap);
                    gap.Should().BeGreaterThanOrEqualTo(MoverKit.HumanRadius - 0.001, $"yaw {yaw}, frame {i} at {speed} m/s: {at}");
                }
            }

            return at;
        }

        foreach (float speed in new[] { 2f, 12f, 50f })
        {
            foreach (int sign in new[] { 1, -1 })
            {
                Vector2 start = Axis + (across * sign * 3f), dir = across * -sign;
                ResolveResult stopped = Walk(start, dir, speed, (int)(6f / (speed * Frame)) + 2);
                Vector2.Dot(new Vector2(stopped.Position.X - hinge.X, stopped.Position.Y - hinge.Y), across * sign).Should()
                    .BeGreaterThan(0.4f, $"closed, the door stops a walker from its {(sign > 0 ? "+Y" : "−Y")} side at {speed} m/s: {stopped}");
            }
        }

        engine.Movers.Open(9);
        engine.Movers.Commit();
        engine.Movers.GetPendingDoorState(9).Should().Be(DoorState.Open);
        ResolveResult through = Walk(Axis + (across * 3f), -across, 4f, 45);
        Vector2.Dot(new Vector2(through.Position.X - hinge.X, through.Position.Y - hinge.Y), across).Should().BeLessThan(-1.5f, $"open, it passes: {through}");

        // A player standing in the doorway (registered) holds the door: told to close, it stays Closing.
        Vector3 inDoor = At(engine, Axis + (across * 0.1f));
        engine.Movers.Add(1, MoverKit.Human, inDoor, Outdoor, Quaternion.Identity, MoverState.Player);
        engine.Movers.Close(9);
        for (int i = 0; i < 3; i++)
        {
            engine.Movers.Commit();
            engine.Movers.GetPendingDoorState(9).Should().Be(DoorState.Closing, $"commit {i}: held while the player stands in it");
        }

        ResolveResult leaving = engine.Resolve(inDoor, Outdoor, new Vector3(across * 2f, 0f), 0.6f, MovementOptions.Player, 1u);
        leaving.Outcome.Should().Be(ResolveOutcome.Moved, $"the held door is Ethereal: the player walks out of it: {leaving}");
        engine.Movers.Move(1, leaving.Position, leaving.CellId, Quaternion.Identity);
        engine.Movers.Commit();
        engine.Movers.GetPendingDoorState(9).Should().Be(DoorState.Closed, "closed at the first commit with nothing in it");
        ResolveResult back = Walk(Axis + (across * 3f), -across, 4f, 60);
        Vector2.Dot(new Vector2(back.Position.X - hinge.X, back.Position.Y - hinge.Y), across).Should().BeGreaterThan(0.4f, $"closed again, it blocks: {back}");
        output.WriteLine($"yaw {yaw}: nearest a closed slab {worst:F6} m (radius {MoverKit.HumanRadius})");
        worst.Should().BeLessThan(MoverKit.HumanRadius + 0.01, "the walkers reached the slab");
    }

    [Theory]
    [InlineData("centred", 0f)]
    [InlineData("centred", 0.3f)]
    [InlineData("global", 0.7f)]
    [InlineData("global", 0.95f)]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_body_falling_onto_a_creature_is_held_on_its_top_and_slides_off(string frame, float offset)
    {
        // A body does not stand on a mover: it is held in the air on the creature's top and slides off outward.
        PhysicsEngine engine = Field(frame);
        Vector3 creature = At(engine, Axis);
        engine.Movers.Add(2, MoverKit.Human, creature, Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        var at = new ResolveResult(creature + new Vector3(offset, 0f, 2.5f), Outdoor, false);
        float vz = 0f;
        int held = 0;
        for (int f = 0; f < 150; f++)
        {
            vz = at.IsOnGround ? 0f : vz - (9.8f * Frame);
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0f, 0f, vz * Frame), 0.6f, MovementOptions.Player);
            string what = $"offset {offset}, frame {f}: {at}";
            if (at.Position.Z < creature.Z + MoverKit.HumanHeight - 0.001f)
            {
                MoverReference.Apart(at.Position, creature).Should().BeGreaterThanOrEqualTo(Touch - 0.001, $"{what}: below the creature's top, beside it");
            }
            else if (MoverReference.Apart(at.Position, creature) < Touch)
            {
                at.IsOnGround.Should().BeFalse($"{what}: held on a mover, not standing");
                held++;
            }
        }

        output.WriteLine($"offset {offset}: held on the top for {held} frames, ended {at}");
        at.IsOnGround.Should().BeTrue($"it slid off and landed: {at}");
        at.Position.Z.Should().Be(Ground);
        held.Should().BeGreaterThan(0, "it came down on the creature's top");
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_fast_fall_that_slides_off_one_creature_never_ends_inside_the_next(string frame)
    {
        // Falls of 1.6 m a call onto a creature's top near its side, another creature beyond that side: the slide off
        // the first (up to half the fall stopped) may carry the body towards the second, which the call must meet too.
        PhysicsEngine engine = Field(frame);
        Vector3 first = At(engine, Axis), second = At(engine, Axis + new Vector2(1.5f, 0f));
        engine.Movers.Add(2, MoverKit.Human, first, Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Add(3, MoverKit.Human, second, Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        foreach (float offset in new[] { 0.2f, 0.4f, 0.6f })
        {
            var at = new ResolveResult(first + new Vector3(offset, 0f, 6f), Outdoor, false);
            for (int f = 0; f < 40 && !at.IsOnGround; f++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(0f, 0f, -1.6f), 0.6f, MovementOptions.Player);
                if (at.Position.Z < first.Z + MoverKit.HumanHeight - 0.001f)
                {
                    MoverReference.Apart(at.Position, first).Should().BeGreaterThanOrEqualTo(Touch - 0.001, $"offset {offset}, call {f}: {at}");
                    MoverReference.Apart(at.Position, second).Should().BeGreaterThanOrEqualTo(Touch - 0.001, $"offset {offset}, call {f}: {at}");
                }
            }

            output.WriteLine($"offset {offset}: {at}");
        }
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_mover_lower_than_the_step_stops_a_body_and_a_point(string frame)
    {
        // A rat: 0.3 m by 0.5 m, under a player's 0.6 m step; a body does not step onto a mover, so it must stop.
        PhysicsEngine engine = Field(frame);
        Vector3 rat = At(engine, Axis);
        engine.Movers.Add(4, MoverShape.Cylinder(0.3f, 0.5f), rat, Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        foreach (float speed in new[] { 2f, 20f, 50f })
        {
            var at = new ResolveResult(At(engine, Axis - new Vector2(3f, 0f)), Outdoor, true);
            for (int i = 0; i < (int)(6f / (speed * Frame)) + 2; i++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(speed * Frame, 0f, 0f), 0.6f, MovementOptions.Player);
                MoverReference.Apart(at.Position, rat).Should().BeGreaterThanOrEqualTo(0.78 - 0.001, $"{speed} m/s, frame {i}: {at}");
            }

            MoverReference.Apart(at.Position, rat).Should().BeLessThan(0.79, $"it reached the rat at {speed} m/s: {at}");
        }

        ResolveResult point = engine.Resolve(At(engine, Axis - new Vector2(2f, 0f)), Outdoor, new Vector3(4f, 0f, 0f), 0.6f);
        point.Outcome.Should().Be(ResolveOutcome.Wall, $"a point crossing it under its step line: {point}");
    }

    [Fact]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_creature_across_a_seam_stops_a_body_in_the_neighbour_landblock()
    {
        const uint east = 0x7B3BFFFF;
        var engine = new PhysicsEngine(Landblock);
        engine.AddLandblock(Landblock, TestData.FlatTerrain(Ground, Landblock), []);
        engine.AddLandblock(east, TestData.FlatTerrain(Ground, east), []);
        Vector3 creature = engine.ToWorld(east, new Vector3(0.3f, 96f, Ground));
        engine.Movers.Add(2, MoverKit.Human, creature, 0x7B3B0000 | 0x0005, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        var at = new ResolveResult(engine.ToWorld(Landblock, new Vector3(189f, 96f, Ground)), Outdoor, true);
        for (int i = 0; i < 40; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0.2f, 0f, 0f), 0.6f, MovementOptions.Player);
            MoverReference.Apart(at.Position, creature).Should().BeGreaterThanOrEqualTo(Touch - 0.001, $"frame {i}: {at}");
        }

        MoverReference.Apart(at.Position, creature).Should().BeLessThan(Touch + 0.01, $"it reached the creature: {at}");
        ResolveResult point = engine.Resolve(engine.ToWorld(Landblock, new Vector3(190f, 96f, Ground)), Outdoor, new Vector3(3f, 0f, 0f), 0.6f);
        point.Outcome.Should().Be(ResolveOutcome.Wall, $"a point crossing it across the seam: {point}");
    }

    [Fact]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_creature_in_a_room_stops_a_body_and_a_point_indoors()
    {
        // The main room of the cottage (0xA9B40143): a creature in its middle.
        (PhysicsEngine engine, _) = HoltburgCells.OnHills(new Random(3), "centred");
        const uint room = 0xA9B40143;
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        engine.TryGetGround(origin + new Vector3(138f, 10f, 95f), room, out float floor, out _).Should().BeTrue();
        Vector3 creature = origin + new Vector3(138f, 10f, floor);
        engine.Movers.Add(2, MoverKit.Human, creature, room, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        var at = new ResolveResult(creature - new Vector3(0f, 2.5f, 0f), room, true);
        int stopped = 0;
        for (int i = 0; i < 40; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0f, 0.15f, 0f), 0.6f, MovementOptions.Player, 0u, [], out _, out MoveReport report);
            MoverReference.Apart(at.Position, creature).Should().BeGreaterThanOrEqualTo(Touch - 0.001, $"frame {i}: {at}");
            stopped += report.Wall.Kind == SurfaceKind.Mover ? 1 : 0;
        }

        stopped.Should().BeGreaterThan(0, $"the creature stopped it: {at}");
        engine.Resolve(creature - new Vector3(0f, 2f, 0f), room, new Vector3(0f, 4f, 0f), 0.6f).Outcome.Should().Be(ResolveOutcome.Wall);
    }
}
