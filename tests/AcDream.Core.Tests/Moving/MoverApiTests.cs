using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;

namespace AcDream.Core.Tests.Moving;

/// <summary>Bad input to the movers is refused with an error naming the argument, the id and what is wrong; moving and committing allocate nothing.</summary>
[Trait("Mutation", "MoverRegistry")]
public class MoverApiTests
{
    private static readonly Vector3 Somewhere = new(100f, 100f, 50f);

    [Fact]
    public void Bad_registrations_and_changes_name_the_argument_and_the_id()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        const uint cell = MoverSmokeTests.Outdoor;
        Action zero = () => movers.Add(0, MoverKit.Human, Somewhere, cell, Quaternion.Identity, MoverState.Creature);
        zero.Should().Throw<ArgumentException>().Where(e => e.ParamName == "id" && e.Message.Contains("0x00000000"));
        movers.Add(7, MoverKit.Human, Somewhere, cell, Quaternion.Identity, MoverState.Creature);
        Action twice = () => movers.Add(7, MoverKit.Human, Somewhere, cell, Quaternion.Identity, MoverState.Creature);
        twice.Should().Throw<ArgumentException>().Where(e => e.ParamName == "id" && e.Message.Contains("0x00000007") && e.Message.Contains("already registered"));
        Action nan = () => movers.Add(8, MoverKit.Human, new Vector3(float.NaN, 0f, 0f), cell, Quaternion.Identity, MoverState.Creature);
        nan.Should().Throw<ArgumentException>().Where(e => e.ParamName == "position" && e.Message.Contains("0x00000008"));
        Action badCell = () => movers.Add(8, MoverKit.Human, Somewhere, 0x7A3B0050, Quaternion.Identity, MoverState.Creature);
        badCell.Should().Throw<ArgumentException>().Where(e => e.ParamName == "cellId" && e.Message.Contains("0x7A3B0050"));
        Action tilted = () => movers.Add(8, MoverKit.Human, Somewhere, cell, Quaternion.CreateFromAxisAngle(Vector3.UnitX, 0.3f), MoverState.Creature);
        tilted.Should().Throw<ArgumentException>().Where(e => e.ParamName == "orientation" && e.Message.Contains("turn about Z"));
        Action none = () => movers.Add(8, MoverKit.Human, Somewhere, cell, default, MoverState.Creature);
        none.Should().Throw<ArgumentException>().Where(e => e.ParamName == "orientation");
        Action noShape = () => movers.Add(8, null!, Somewhere, cell, Quaternion.Identity, MoverState.Creature);
        noShape.Should().Throw<ArgumentNullException>().Where(e => e.ParamName == "shape");
        Action unknown = () => movers.Move(9, Somewhere, cell, Quaternion.Identity);
        unknown.Should().Throw<ArgumentException>().Where(e => e.ParamName == "id" && e.Message.Contains("0x00000009") && e.Message.Contains("not registered"));
        Action notADoor = () => movers.Open(7);
        notADoor.Should().Throw<ArgumentException>().Where(e => e.ParamName == "doorId" && e.Message.Contains("0x00000007"));
        movers.Remove(9).Should().BeFalse();
        movers.Count.Should().Be(1, "a refused change changes nothing");

        Action thin = () => MoverShape.Cylinder(0f, 1f);
        thin.Should().Throw<ArgumentOutOfRangeException>().Where(e => e.ParamName == "radius");
        Action flat = () => MoverShape.Cylinder(0.5f, float.PositiveInfinity);
        flat.Should().Throw<ArgumentOutOfRangeException>().Where(e => e.ParamName == "height");
        Action floorOnly = () => new MoverShape(Robustness.ObjectKit.Gfx(0x01000042, new Vector3[] { new(0, 0, 0), new(1, 0, 0), new(1, 1, 0) }));
        floorOnly.Should().Throw<ArgumentException>().Where(e => e.ParamName == "gfxObj" && e.Message.Contains("0x01000042") && e.Message.Contains("no walls"));
    }

    [Fact]
    public void Moving_a_thousand_creatures_and_committing_allocates_nothing()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        for (uint i = 1; i <= 1000; i++)
        {
            engine.Movers.Add(i, MoverKit.Human, MoverSmokeTests.World(engine, new Vector2(i % 180, i / 6f)), MoverSmokeTests.Outdoor, Quaternion.Identity, MoverState.Creature);
        }

        long bytes = 0;
        for (int f = 0; f < 6; f++)
        {
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (uint i = 1; i <= 1000; i++)
            {
                engine.Movers.Move(i, MoverSmokeTests.World(engine, new Vector2((i % 180) + (f * 0.1f), i / 6f)), MoverSmokeTests.Outdoor, MoverReference.Yaw(f));
            }

            engine.Movers.Commit();
            bytes = GC.GetAllocatedBytesForCurrentThread() - before;
        }

        bytes.Should().Be(0, "after the first commits have made their states, a frame of moves and its commit allocate nothing");
    }

    [Fact]
    public void Removing_a_landblock_removes_its_movers_only()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        engine.Movers.Add(1, MoverKit.Human, Somewhere, MoverSmokeTests.Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Add(2, MoverKit.Human, Somewhere, 0x7A3B0105, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Add(3, MoverKit.Human, Somewhere + new Vector3(192f, 0f, 0f), 0x7B3B0001, Quaternion.Identity, MoverState.Creature);
        engine.Movers.RemoveLandblock(0x7A3BFFFF).Should().Be(2);
        engine.Movers.Count.Should().Be(1);
        engine.Movers.GetState(3).Should().Be(MoverState.Creature);
    }
}
