using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;

namespace AcDream.Core.Tests.Moving;

/// <summary>
/// The registry of movers on its own terms: where a mover's walls are placed for each turn (a quaternion of any length),
/// which orientations are refused, what removing, moving and committing leave behind for the movers that stay, the doors'
/// states through every change, and the committed states a call reads: never the one being written, whole when read.
/// Each mover is probed with rays (exact contacts) on flat ground.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class MoverRegistryTests
{
    private const uint Landblock = MoverSmokeTests.Landblock;
    private const uint Outdoor = 0x7A3B0025; // the outdoor cell of (100, 100)
    private const float Ground = MoverSmokeTests.Ground;
    private const int LandblockX = 0x7A, LandblockY = 0x3B;

    private static readonly Vector2 Door = new(100f, 100f);

    private static Vector3 At(PhysicsEngine engine, Vector2 local, float up = 0f) => engine.ToWorld(Landblock, new Vector3(local, Ground + up));

    /// <summary>A ray 1 m above the ground from <paramref name="from"/> to <paramref name="to"/> (local), meeting movers only as they are.</summary>
    private static CastHit Ray(PhysicsEngine engine, Vector2 from, Vector2 to, uint landblock = Landblock) =>
        engine.Cast(engine.ToWorld(landblock, new Vector3(from, Ground + 1f)), 0, engine.ToWorld(landblock, new Vector3(to, Ground + 1f)), new CastOptions(0f));

    /// <summary>Where a ray along +X at y = 0 (relative to the slab's centre) first enters the game's slab of width 1.2 turned by <paramref name="yaw"/>: −∞..+∞ in x, the first x inside.</summary>
    private static double SlabEntry(double yaw)
    {
        // Local u = c·x, v = −s·x for a point (x, 0): |u| ≤ 0.6 and SlabNear ≤ v ≤ SlabFar.
        double c = Math.Cos(yaw), s = Math.Sin(yaw), lo = double.NegativeInfinity, hi = double.PositiveInfinity;
        Clip(c, -0.6, 0.6);
        Clip(-s, MoverReference.SlabNear, MoverReference.SlabFar);
        return lo <= hi ? lo : double.NaN;

        void Clip(double k, double min, double max)
        {
            if (Math.Abs(k) < 1e-12)
            {
                return;
            }

            double a = min / k, b = max / k;
            (lo, hi) = (Math.Max(lo, Math.Min(a, b)), Math.Min(hi, Math.Max(a, b)));
        }
    }

    [Theory]
    [InlineData(0.0)]
    [InlineData(0.5)]
    [InlineData(Math.PI / 2)]
    [InlineData(-Math.PI / 2)]
    [InlineData(2.5)]
    [InlineData(-2.0)]
    public void A_slab_is_placed_turned_by_its_orientation_whatever_its_length(double yaw)
    {
        double expected = SlabEntry(yaw);
        foreach (float scale in new[] { 1f, 3f, 0.05f })
        {
            PhysicsEngine engine = MoverSmokeTests.Field();
            engine.Movers.Add(9, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), At(engine, Door), Outdoor, MoverReference.Yaw(yaw) * scale, MoverState.Door);
            engine.Movers.Commit();
            CastHit hit = Ray(engine, Door - new Vector2(3f, 0f), Door + new Vector2(3f, 0f));
            hit.Hit.Should().BeTrue($"yaw {yaw}, scale {scale}");
            hit.Kind.Should().Be(SurfaceKind.Mover);
            hit.Id.Should().Be(9u);
            double x = hit.Position.X - At(engine, Door).X;
            x.Should().BeApproximately(expected, 2e-5, $"yaw {yaw}, scale {scale}");
        }
    }

    [Fact]
    public void A_turn_whose_X_and_Y_are_within_a_thousandth_of_its_length_is_taken_as_its_turn_about_Z()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        Quaternion turn = MoverReference.Yaw(Math.PI / 2);
        engine.Movers.Add(9, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), At(engine, Door), Outdoor, turn with { X = 0.0009f }, MoverState.Door);
        engine.Movers.Commit();
        Ray(engine, Door - new Vector2(3f, 0f), Door + new Vector2(3f, 0f)).Position.X.Should().BeApproximately(At(engine, Door).X - MoverReference.SlabFar, 2e-4f);
        engine.Movers.Move(9, At(engine, Door), Outdoor, (turn * 2f) with { Y = -0.0019f });
        engine.Movers.Commit();
        Ray(engine, Door - new Vector2(3f, 0f), Door + new Vector2(3f, 0f)).Position.X.Should().BeApproximately(At(engine, Door).X - MoverReference.SlabFar, 2e-4f);
    }

    [Fact]
    public void Orientations_that_are_not_a_turn_about_Z_are_refused_naming_the_id()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        Vector3 p = At(engine, Door);
        foreach (Quaternion q in new[]
        {
            new Quaternion(0f, 0f, 0f, 1e-7f), new Quaternion(0f, 0f, 5e-7f, 0f), new Quaternion(0.0011f, 0f, 0f, 1f), new Quaternion(0f, -0.0011f, 0f, 1f),
            new Quaternion(0.0021f, 0f, 0f, 2f), new Quaternion(0f, 0f, 0f, float.PositiveInfinity), new Quaternion(0f, 0f, float.NaN, 1f),
            new Quaternion(float.NaN, 0f, 0f, 1f),
        })
        {
            Action add = () => movers.Add(5, MoverKit.Human, p, Outdoor, q, MoverState.Creature);
            add.Should().Throw<ArgumentException>().Where(e => e.ParamName == "orientation" && e.Message.Contains("0x00000005") && e.Message.Contains("turn about Z"), $"{q}");
        }

        movers.Count.Should().Be(0);
        foreach (Quaternion q in new[]
        {
            new Quaternion(0f, 0f, 0f, 1e-5f), new Quaternion(0f, 0f, 2e-6f, 0f), new Quaternion(0.0009f, 0f, 0f, 1f), new Quaternion(0f, 0.0019f, 0f, 2f),
            new Quaternion(0.0019f, 0f, 0f, 2f), new Quaternion(0.001f, 0f, 0f, 1f), new Quaternion(0f, -0.001f, 0f, 1f), new Quaternion(0.001f, 0f, 0.6f, -0.8f),
            new Quaternion(0f, 0f, 1e30f, 1e30f), new Quaternion(0f, 0f, 3e38f, 3e38f),
        })
        {
            movers.Add(5, MoverKit.Human, p, Outdoor, q, MoverState.Creature);
            movers.Remove(5).Should().BeTrue();
        }

        Action zero = () => movers.Add(0, MoverKit.Human, p, Outdoor, Quaternion.Identity, MoverState.Creature);
        zero.Should().Throw<ArgumentException>().WithMessage("mover 0x00000000: 0 is not an id.*");
        movers.Add(6, MoverKit.Human, p, Outdoor, Quaternion.Identity, MoverState.Creature);
        Action twice = () => movers.Add(6, MoverKit.Human, p, Outdoor, Quaternion.Identity, MoverState.Creature);
        twice.Should().Throw<ArgumentException>().WithMessage("mover 0x00000006: already registered.*");
        Action infinite = () => movers.Move(6, new Vector3(float.PositiveInfinity, 0f, 0f), Outdoor, Quaternion.Identity);
        infinite.Should().Throw<ArgumentException>().Where(e => e.ParamName == "position" && e.Message.Contains("0x00000006") && e.Message.Contains("finite"));
        Action badCell = () => movers.Move(6, p, 0x7A3B0050, Quaternion.Identity);
        badCell.Should().Throw<ArgumentException>().Where(e => e.ParamName == "cellId" && e.Message.Contains("0x7A3B0050") && e.Message.Contains("0x00000006"));
        Action unknownState = () => movers.GetState(8);
        unknownState.Should().Throw<ArgumentException>().Where(e => e.ParamName == "id" && e.Message.Contains("0x00000008 is not registered"));
        Action setUnknown = () => movers.SetState(8, MoverState.Creature);
        setUnknown.Should().Throw<ArgumentException>().Where(e => e.ParamName == "id");
        Action closeUnknown = () => movers.Close(8);
        closeUnknown.Should().Throw<ArgumentException>().Where(e => e.ParamName == "doorId" && e.Message.Contains("0x00000008 is not a registered door"));
        Action stateOfCreature = () => movers.GetPendingDoorState(6);
        stateOfCreature.Should().Throw<ArgumentException>().Where(e => e.ParamName == "doorId" && e.Message.Contains("0x00000006"));

        // A refused move leaves the mover where it was.
        movers.Commit();
        Ray(engine, Door - new Vector2(3f, 0f), Door + new Vector2(3f, 0f)).Id.Should().Be(6u);
        movers.Count.Should().Be(1);
    }

    [Fact]
    public void Removing_and_moving_movers_leaves_each_of_the_others_where_it_is()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        float[] xs = [100f, 104f, 108f, 112f, 116f];
        for (uint i = 0; i < xs.Length; i++)
        {
            movers.Add(i + 1, MoverKit.Human, At(engine, new Vector2(xs[i], 100f)), Outdoor, Quaternion.Identity, MoverState.Creature);
        }

        uint Across(float x) => Ray(engine, new Vector2(x, 96f), new Vector2(x, 104f)) is { Hit: true } h ? h.Id : 0u;
        movers.Commit();
        xs.Select(Across).Should().Equal(1u, 2u, 3u, 4u, 5u);
        movers.Count.Should().Be(5);

        movers.Remove(1).Should().BeTrue(); // the last takes its slot
        movers.Remove(1).Should().BeFalse();
        movers.Count.Should().Be(4);
        movers.Commit();
        xs.Select(Across).Should().Equal(0u, 2u, 3u, 4u, 5u);

        movers.Move(5, At(engine, new Vector2(100f, 100f)), Outdoor, Quaternion.Identity);
        movers.Move(3, At(engine, new Vector2(116f, 100f)), Outdoor, Quaternion.Identity);
        movers.Commit();
        xs.Select(Across).Should().Equal(5u, 2u, 0u, 4u, 3u);
        movers.Remove(2).Should().BeTrue();
        movers.SetState(4, MoverState.Creature with { Physics = PhysicsStateFlags.Ethereal | PhysicsStateFlags.IgnoreCollisions });
        movers.Commit();
        xs.Select(Across).Should().Equal(5u, 0u, 0u, 0u, 3u);
        movers.GetState(4).Physics.Should().Be(PhysicsStateFlags.Ethereal | PhysicsStateFlags.IgnoreCollisions);
        movers.GetState(5).Should().Be(MoverState.Creature);

        // A new mover of another shape in a freed slot: placed with its own walls.
        movers.Add(7, MoverShape.Cylinder(0.2f, 1.835f), At(engine, new Vector2(108f, 100.5f)), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Commit();
        Across(108f).Should().Be(7u);
        Ray(engine, new Vector2(108f, 96f), new Vector2(108f, 104f)).Position.Y.Should().BeApproximately(At(engine, new Vector2(108f, 100.3f)).Y, 1e-4f);
        Across(107.75f).Should().Be(0u, "its radius is 0.2 m");
        movers.Count.Should().Be(4);
    }

    [Fact]
    public void Committing_with_no_mover_left_commits_none()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        engine.Movers.Add(1, MoverKit.Human, At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Any.Should().BeFalse("nothing committed yet");
        engine.Movers.Commit();
        engine.Movers.Any.Should().BeTrue();
        Ray(engine, Door - new Vector2(3f, 0f), Door + new Vector2(3f, 0f)).Id.Should().Be(1u);
        engine.Movers.Remove(1);
        engine.Movers.Any.Should().BeTrue("the removal is not committed");
        engine.Movers.Commit();
        engine.Movers.Any.Should().BeFalse();
        engine.Movers.Hold().Should().BeNull();
        Ray(engine, Door - new Vector2(3f, 0f), Door + new Vector2(3f, 0f)).Hit.Should().BeFalse();
    }

    [Fact]
    public void Removing_a_landblock_leaves_the_movers_of_the_others_in_place()
    {
        const uint east = 0x7B3BFFFF;
        PhysicsEngine engine = MoverSmokeTests.Field();
        engine.AddLandblock(east, TestData.FlatTerrain(Ground, east), []);
        MoverRegistry movers = engine.Movers;
        for (uint i = 0; i < 8; i++)
        {
            bool home = i % 3 != 1;
            uint lb = home ? Landblock : east;
            movers.Add(i + 1, MoverKit.Human, engine.ToWorld(lb, new Vector3(20f + (4f * i), 100f, Ground)), home ? Outdoor : 0x7B3B0001, Quaternion.Identity, MoverState.Creature);
        }

        movers.Commit();
        movers.RemoveLandblock(Landblock).Should().Be(5);
        movers.Count.Should().Be(3);
        movers.Commit();
        for (uint i = 0; i < 8; i++)
        {
            bool home = i % 3 != 1;
            uint lb = home ? Landblock : east;
            CastHit hit = Ray(engine, new Vector2(20f + (4f * i), 96f), new Vector2(20f + (4f * i), 104f), lb);
            hit.Id.Should().Be(home ? 0u : i + 1, $"mover {i + 1}");
            if (!home)
            {
                movers.GetState(i + 1).Should().Be(MoverState.Creature);
            }
        }

        movers.RemoveLandblock(Landblock).Should().Be(0);
        movers.RemoveLandblock(east).Should().Be(3);
        movers.Count.Should().Be(0);
    }

    [Fact]
    public void A_door_moves_through_its_states_by_every_change()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        movers.Add(9, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Door);
        movers.Commit();
        movers.Close(9); // closing a closed door: nothing to do
        movers.GetPendingDoorState(9).Should().Be(DoorState.Closed);
        movers.Commit();
        movers.GetPendingDoorState(9).Should().Be(DoorState.Closed);

        // Held open by a creature standing in it: Closing; opened again, Open, and it stays open once the creature leaves.
        movers.Add(2, MoverKit.Human, At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Open(9);
        movers.Commit();
        movers.Close(9);
        movers.Commit();
        movers.GetPendingDoorState(9).Should().Be(DoorState.Closing);
        movers.Open(9);
        movers.GetPendingDoorState(9).Should().Be(DoorState.Open);
        movers.Move(2, At(engine, Door + new Vector2(5f, 0f)), Outdoor, Quaternion.Identity);
        movers.Commit();
        movers.GetPendingDoorState(9).Should().Be(DoorState.Open, "opened again, it is not closing");
        movers.GetState(9).Physics.Should().HaveFlag(PhysicsStateFlags.Ethereal);

        // Closing, then given a state: the state is the door's, and it closes no more by itself.
        movers.Move(2, At(engine, Door), Outdoor, Quaternion.Identity);
        movers.Commit();
        movers.Close(9);
        movers.Commit();
        movers.GetPendingDoorState(9).Should().Be(DoorState.Closing);
        movers.SetState(9, MoverState.Door with { Physics = PhysicsStateFlags.Ethereal });
        movers.GetPendingDoorState(9).Should().Be(DoorState.Open);
        movers.Move(2, At(engine, Door + new Vector2(5f, 0f)), Outdoor, Quaternion.Identity);
        movers.Commit();
        movers.GetPendingDoorState(9).Should().Be(DoorState.Open);
        movers.SetState(9, MoverState.Door);
        movers.GetPendingDoorState(9).Should().Be(DoorState.Closed);
    }

    [Theory]
    [InlineData("door", false)]
    [InlineData("ethereal ignoring", false)]
    [InlineData("ethereal", true)]
    [InlineData("creature", true)]
    [InlineData("object", true)]
    [InlineData("far", false)]
    [InlineData("slab", false)]
    public void A_door_is_held_open_by_a_mover_standing_in_it_that_is_met_and_is_not_a_door(string what, bool holds)
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        movers.Add(9, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Door);
        (MoverShape shape, MoverState state, Vector2 at) = what switch
        {
            "door" => (MoverKit.Human, MoverState.Door, Door),
            "ethereal ignoring" => (MoverKit.Human, MoverState.Creature with { Physics = PhysicsStateFlags.Ethereal | PhysicsStateFlags.IgnoreCollisions }, Door),
            "ethereal" => (MoverKit.Human, MoverState.Creature with { Physics = PhysicsStateFlags.Ethereal }, Door),
            "creature" => (MoverKit.Human, MoverState.Creature, Door + new Vector2(0.5f, 0.6f)),
            "object" => (MoverShape.Cylinder(0.3f, 1f), new MoverState(MoverKind.Object), Door + new Vector2(-0.7f, -0.25f)),
            "far" => (MoverKit.Human, MoverState.Creature, Door + new Vector2(0f, 0.252f + 0.48f + 0.01f)),
            _ => (new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), MoverState.Creature, Door + new Vector2(0.3f, 0.1f)), // walls, no cylinder
        };
        movers.Add(2, shape, At(engine, at), Outdoor, Quaternion.Identity, state);
        movers.Open(9);
        movers.Commit();
        movers.Close(9);
        movers.Commit();
        movers.GetPendingDoorState(9).Should().Be(holds ? DoorState.Closing : DoorState.Closed, what);
        movers.GetPendingDoorState(9).Should().Be(holds ? DoorState.Closing : DoorState.Closed, what);
        if (holds)
        {
            movers.Remove(2);
            movers.Commit();
            movers.GetPendingDoorState(9).Should().Be(DoorState.Closed, $"{what}: gone, the door closes");
        }
    }

    [Theory]
    [InlineData(1, 0)]
    [InlineData(-1, 0)]
    [InlineData(0, 1)]
    [InlineData(0, -1)]
    public void A_door_across_a_seam_is_met_in_the_neighbour_and_held_by_a_creature_standing_there(int dx, int dy)
    {
        uint neighbour = (uint)(((LandblockX + dx) << 24) | ((LandblockY + dy) << 16) | 0xFFFF);
        PhysicsEngine engine = MoverSmokeTests.Field();
        engine.AddLandblock(neighbour, TestData.FlatTerrain(Ground, neighbour), []);
        MoverRegistry movers = engine.Movers;

        // The slab turned so it lies across the seam: centred 0.2 m inside this landblock, reaching 0.4 m into the next.
        const float side = 192f;
        var centre = new Vector2(dx > 0 ? side - 0.2f : dx < 0 ? 0.2f : 100f, dy > 0 ? side - 0.2f : dy < 0 ? 0.2f : 100f);
        double yaw = dx != 0 ? 0 : Math.PI / 2;
        uint cell = (uint)(0x7A3B0000 | (((int)(centre.X / 24f) * 8) + (int)(centre.Y / 24f) + 1));
        movers.Add(9, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), engine.ToWorld(Landblock, new Vector3(centre, Ground)), cell, MoverReference.Yaw(yaw), MoverState.Door);
        movers.Commit();

        // A ray wholly in the neighbour crossing the slab's part there, 0.3 m past the seam, meets it.
        var along = new Vector2(dy != 0 ? 1f : 0f, dx != 0 ? 1f : 0f);
        Vector2 inNeighbour = centre + new Vector2(dx * 0.5f, dy * 0.5f) - new Vector2(dx * side, dy * side);
        CastHit hit = Ray(engine, inNeighbour - (along * 2f), inNeighbour + (along * 2f), neighbour);
        hit.Hit.Should().BeTrue($"{dx}, {dy}");
        hit.Id.Should().Be(9u);

        // A creature standing in the neighbour over that part holds it open.
        Vector3 there = engine.ToWorld(neighbour, new Vector3(inNeighbour, Ground));
        uint neighbourCell = (uint)((neighbour & 0xFFFF0000) | (uint)(((int)(inNeighbour.X / 24f) * 8) + (int)(inNeighbour.Y / 24f) + 1));
        movers.Add(2, MoverShape.Cylinder(0.1f, 1f), there, neighbourCell, Quaternion.Identity, MoverState.Creature);
        movers.Open(9);
        movers.Commit();
        movers.Close(9);
        movers.Commit();
        movers.GetPendingDoorState(9).Should().Be(DoorState.Closing, $"{dx}, {dy}");
        movers.Move(2, there + new Vector3(dx * 2f, dy * 2f, 0f), neighbourCell, Quaternion.Identity);
        movers.Commit();
        movers.GetPendingDoorState(9).Should().Be(DoorState.Closed, $"{dx}, {dy}");
    }

    [Fact]
    public void A_state_read_unheld_is_whole_and_answers_whether_a_mover_is_near()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        movers.NoneNear(LandblockX, LandblockY, new Vector2(90f), new Vector2(110f), out MoverFrame? none).Should().BeTrue("none committed");
        none.Should().BeNull();
        movers.Add(1, MoverKit.Human, At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Commit();
        movers.NoneNear(LandblockX, LandblockY, new Vector2(90f), new Vector2(110f), out MoverFrame? near).Should().BeFalse();
        near.Should().NotBeNull();
        near!.Count.Should().Be(1);
        movers.NoneNear(LandblockX, LandblockY, new Vector2(150f), new Vector2(170f), out MoverFrame? far).Should().BeTrue("none near that box");
        far.Should().BeNull();
        movers.NoneNear(LandblockX + 1, LandblockY, new Vector2(90f), new Vector2(110f), out _).Should().BeTrue("none in the next landblock");

        // Being written (its sequence odd), a state read unheld is not whole: neither answer.
        MoverFrame current = movers.Hold()!;
        MoverRegistry.Release(current);
        current.Sequence++;
        movers.NoneNear(LandblockX, LandblockY, new Vector2(150f), new Vector2(170f), out MoverFrame? torn).Should().BeFalse();
        torn.Should().BeNull();
        movers.NoneNear(LandblockX, LandblockY, new Vector2(90f), new Vector2(110f), out torn).Should().BeFalse();
        torn.Should().BeNull();
        current.Sequence++;
        movers.NoneNear(LandblockX, LandblockY, new Vector2(150f), new Vector2(170f), out _).Should().BeTrue();
    }

    [Fact]
    public void A_commit_never_rewrites_the_state_current_or_held()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        movers.Add(1, MoverKit.Human, At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Commit();
        MoverFrame first = movers.Hold()!;
        MoverRegistry.Release(first);
        (first.Sequence & 1).Should().Be(0, "whole");
        movers.Commit();
        MoverFrame second = movers.Hold()!;
        MoverRegistry.Release(second);
        second.Should().NotBeSameAs(first, "the state current when the commit began may be being read unheld");
        movers.Commit();
        MoverFrame third = movers.Hold()!;
        third.Should().BeSameAs(first, "neither current nor held: written again");

        // Held (third), and the current one after the next commit: a third state is made for the commit after.
        movers.Commit();
        MoverFrame fourth = movers.Hold()!;
        MoverRegistry.Release(fourth);
        fourth.Should().BeSameAs(second);
        movers.Move(1, At(engine, Door + new Vector2(10f, 0f)), Outdoor, Quaternion.Identity);
        movers.Commit();
        MoverFrame fifth = movers.Hold()!;
        MoverRegistry.Release(fifth);
        fifth.Should().NotBeSameAs(third).And.NotBeSameAs(fourth);
        third.Walls[0].Min.X.Should().BeApproximately(Door.X - MoverKit.HumanRadius, 1e-3f, "the held state still has the mover where it was");
        fifth.Walls[0].Min.X.Should().BeApproximately(Door.X + 10f - MoverKit.HumanRadius, 1e-3f);
        third.Readers.Should().Be(1);
        MoverRegistry.Release(third);
        third.Readers.Should().Be(0);
        MoverRegistry.Release(null);
    }

    [Fact]
    public void Every_state_committed_has_each_change_however_changes_removals_and_commits_interleave()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        uint Across(float x) => Ray(engine, new Vector2(x, 96f), new Vector2(x, 104f)) is { Hit: true } h ? h.Id : 0u;
        Vector3 P(float x) => At(engine, new Vector2(x, 100f));
        void Seen(params (float X, uint Id)[] expected)
        {
            foreach ((float x, uint id) in expected)
            {
                Across(x).Should().Be(id, $"at x {x}");
            }
        }

        // Added, moved, committed twice (both states written), removed; another added in its slot and moved.
        movers.Add(1, MoverKit.Human, P(100f), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Move(1, P(104f), Outdoor, Quaternion.Identity);
        movers.Commit();
        movers.Commit();
        movers.Remove(1);
        movers.Add(2, MoverKit.Human, P(108f), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Move(2, P(112f), Outdoor, Quaternion.Identity);
        for (int c = 0; c < 3; c++)
        {
            movers.Commit();
            Seen((100f, 0u), (104f, 0u), (108f, 0u), (112f, 2u));
        }

        // Moved between commits with another added in between.
        movers.Move(2, P(116f), Outdoor, Quaternion.Identity);
        movers.Commit();
        movers.Add(3, MoverKit.Human, P(130f), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Move(2, P(120f), Outdoor, Quaternion.Identity);
        for (int c = 0; c < 3; c++)
        {
            movers.Commit();
            Seen((112f, 0u), (116f, 0u), (120f, 2u), (130f, 3u));
        }

        // The first of two removed after both states were written: the other takes its slot.
        movers.Add(4, MoverKit.Human, P(140f), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Commit();
        movers.Commit();
        movers.Remove(2);
        for (int c = 0; c < 3; c++)
        {
            movers.Commit();
            Seen((120f, 0u), (130f, 3u), (140f, 4u));
        }
    }

    [Fact]
    public void Removing_a_landblock_of_as_many_movers_as_the_registry_holds_forgets_every_id()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        for (int n = 15; n <= 17; n++)
        {
            for (uint i = 1; i <= n; i++)
            {
                movers.Add(i, MoverKit.Human, At(engine, new Vector2(10f * i, 50f)), Outdoor, Quaternion.Identity, MoverState.Creature);
            }

            movers.Commit();
            movers.RemoveLandblock(Landblock).Should().Be(n);
            movers.Count.Should().Be(0);
            Action state = () => movers.GetState(3);
            state.Should().Throw<ArgumentException>().Where(e => e.ParamName == "id");
            movers.Remove(5).Should().BeFalse();
            movers.Commit();
            movers.Any.Should().BeFalse();
        }

        movers.Add(3, MoverKit.Human, At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Commit();
        Ray(engine, Door - new Vector2(3f, 0f), Door + new Vector2(3f, 0f)).Id.Should().Be(3u);
    }

    [Theory]
    [InlineData(16)]
    [InlineData(32)]
    public void Moving_and_committing_as_many_movers_as_the_registry_has_room_for_allocates_nothing(int n)
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        movers.Add(100, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Door);
        for (uint i = 1; i < n; i++)
        {
            movers.Add(i, MoverKit.Human, At(engine, new Vector2(5f * i, 20f)), Outdoor, Quaternion.Identity, MoverState.Creature);
        }

        movers.Open(100);
        long bytes = 0;
        for (int f = 0; f < 5; f++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (uint i = 1; i < n; i++)
            {
                movers.Move(i, At(engine, new Vector2(5f * i, 20f + (0.1f * f))), Outdoor, Quaternion.Identity);
            }

            movers.Close(100);
            movers.Commit();
            bytes = GC.GetAllocatedBytesForCurrentThread() - before;
        }

        bytes.Should().Be(0);
        movers.GetPendingDoorState(100).Should().Be(DoorState.Closed);
        Ray(engine, new Vector2(15f, 16f), new Vector2(15f, 26f)).Id.Should().Be(3u);
    }

    [Fact]
    public void A_mover_moved_away_leaves_no_mark_where_it_was()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        movers.Add(1, MoverKit.Human, At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Commit();
        movers.Commit();
        movers.NoneNear(LandblockX, LandblockY, Door - new Vector2(2f), Door + new Vector2(2f), out _).Should().BeFalse();
        movers.Move(1, At(engine, new Vector2(160f, 160f)), 0x7A3B0037, Quaternion.Identity);
        for (int c = 0; c < 3; c++)
        {
            movers.Commit();
            movers.NoneNear(LandblockX, LandblockY, Door - new Vector2(2f), Door + new Vector2(2f), out _).Should().BeTrue($"commit {c}");
            movers.NoneNear(LandblockX, LandblockY, new Vector2(158f), new Vector2(162f), out _).Should().BeFalse();
        }
    }

    [Theory]
    [InlineData(-1, 0)]
    [InlineData(1, 0)]
    [InlineData(0, -1)]
    [InlineData(0, 1)]
    public void A_mover_whose_walls_end_exactly_on_a_seam_marks_no_cell_of_the_neighbour(int dx, int dy)
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;

        // A cylinder of 0.5 m 0.5 m from the seam: its walls reach the seam and no further.
        var at = new Vector2(dx < 0 ? 0.5f : dx > 0 ? 191.5f : 100f, dy < 0 ? 0.5f : dy > 0 ? 191.5f : 100f);
        uint cell = (uint)(0x7A3B0000 | (((int)(at.X / 24f) * 8) + (int)(at.Y / 24f) + 1));
        movers.Add(1, MoverShape.Cylinder(0.5f, 2f), At(engine, at), cell, Quaternion.Identity, MoverState.Creature);
        movers.Commit();
        MoverFrame frame = movers.Hold()!;
        MoverRegistry.Release(frame);
        (dx < 0 ? frame.Walls[0].Min.X : dx > 0 ? frame.Walls[0].Max.X : dy < 0 ? frame.Walls[0].Min.Y : frame.Walls[0].Max.Y).Should().Be(dx + dy < 0 ? 0f : 192f);

        // A box 1..7 m into the neighbour, along the seam where the mover stands: none near. The mover's own side: near.
        Vector2 Across(float depth) => new(dx == 0 ? at.X : dx < 0 ? 192f - depth : depth, dy == 0 ? at.Y : dy < 0 ? 192f - depth : depth);
        Vector2 a = Across(1f), b = Across(7f);
        Vector2 lo = Vector2.Min(a, b) - new Vector2(dx == 0 ? 2f : 0f, dy == 0 ? 2f : 0f), hi = Vector2.Max(a, b) + new Vector2(dx == 0 ? 2f : 0f, dy == 0 ? 2f : 0f);
        movers.NoneNear(LandblockX + dx, LandblockY + dy, lo, hi, out _).Should().BeTrue($"{dx}, {dy}: {lo}..{hi}");
        movers.NoneNear(LandblockX, LandblockY, at - new Vector2(1f), at + new Vector2(1f), out _).Should().BeFalse();
    }

    [Fact]
    public void Many_walkers_each_move_by_their_own_state()
    {
        // Forty creatures, then forty walkers that ignore creatures, each 1.5 m behind one (ids 256 apart, so each pair
        // shares its place in any table of ids hashed by their low bits): each walker walks through its creature,
        // touching it.
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        var walker = new MoverState(MoverKind.Creature, IgnoresCreatures: true);
        static Vector2 Spot(uint i) => new(10f + (4f * ((i - 1) % 10)), 20f + (4f * ((i - 1) / 10)));
        for (uint i = 1; i <= 40; i++)
        {
            movers.Add(i, MoverKit.Human, At(engine, Spot(i) + new Vector2(1.5f, 0f)), Outdoor, Quaternion.Identity, MoverState.Creature);
        }

        for (uint i = 1; i <= 40; i++)
        {
            movers.Add(256 + i, MoverKit.Human, At(engine, Spot(i)), Outdoor, Quaternion.Identity, walker);
        }

        movers.Commit();
        Span<uint> touched = stackalloc uint[8];
        for (uint i = 1; i <= 40; i++)
        {
            ResolveResult r = engine.Resolve(At(engine, Spot(i)), Outdoor, new Vector3(3f, 0f, 0f), 0.6f, MovementOptions.Player, 256 + i, touched, out int count, out _);
            r.Outcome.Should().Be(ResolveOutcome.Moved, $"walker {256 + i}: {r}");
            count.Should().Be(1, $"walker {256 + i}");
            touched[0].Should().Be(i);
        }
    }

    [Fact]
    public void An_id_filed_in_the_last_slot_of_the_states_table_of_ids_is_found()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        movers.Add(1, MoverKit.Human, At(engine, Door), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Commit();
        MoverFrame frame = movers.Hold()!;
        MoverRegistry.Release(frame);
        uint last = 2;
        while (frame.IdSlot(last) != frame.Mask)
        {
            last++;
        }

        var state = new MoverState(MoverKind.Creature, IgnoresCreatures: true);
        movers.Add(last, MoverKit.Human, At(engine, Door + new Vector2(0f, 10f)), Outdoor, Quaternion.Identity, state);
        movers.Commit();
        movers.Commit();
        MoverFrame now = movers.Hold()!;
        MoverRegistry.Release(now);
        now.Mask.Should().Be(frame.Mask, "the same table");
        now.StateOf(last).Should().Be(state);
        now.StateOf(1).Should().Be(MoverState.Creature);
        now.StateOf(last + 1).Should().Be(MoverState.Unregistered);
    }
}
