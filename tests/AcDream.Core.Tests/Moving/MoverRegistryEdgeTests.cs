using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Moving;

/// <summary>
/// The registry at its edges: an orientation whose X or Y is exactly a thousandth of its length (the limit, taken as a
/// turn about Z), and a mover that becomes a door by <see cref="MoverRegistry.SetState"/>, which has no committed door
/// state until the next commit.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
public class MoverRegistryEdgeTests
{
    private const uint Outdoor = 0x7A3B0025;

    private static Vector3 At(PhysicsEngine engine, float x, float y) =>
        engine.ToWorld(MoverSmokeTests.Landblock, new Vector3(x, y, MoverSmokeTests.Ground));

    /// <summary>|X| (or |Y|) = 1e-3 · length exactly, in the double the registry works in; one float more is beyond it.</summary>
    private static readonly float Tilt = BitConverter.UInt32BitsToSingle(0x3A831271), Z = BitConverter.UInt32BitsToSingle(0x3A24C7B4), W = BitConverter.UInt32BitsToSingle(0x3F7FFFF9);

    private static double Length(Quaternion q) =>
        Math.Sqrt(((double)q.W * q.W) + ((double)q.Z * q.Z) + ((double)q.X * q.X) + ((double)q.Y * q.Y));

    [Fact]
    public void An_orientation_whose_X_or_Y_is_exactly_a_thousandth_of_its_length_is_a_turn_about_Z()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        Vector3 p = At(engine, 100f, 100f);
        float beyond = BitConverter.UInt32BitsToSingle(0x3A831272);
        foreach (Quaternion atLimit in new[] { new Quaternion(Tilt, 0f, Z, W), new Quaternion(0f, Tilt, Z, W), new Quaternion(0f, -Tilt, Z, W) })
        {
            Math.Abs((double)(atLimit.X + atLimit.Y)).Should().Be(1e-3 * Length(atLimit), $"{atLimit} is at the limit");
            movers.Add(5, MoverKit.Human, p, Outdoor, atLimit, MoverState.Creature);
            movers.Remove(5).Should().BeTrue();

            Quaternion over = atLimit.X != 0f ? atLimit with { X = beyond } : atLimit with { Y = Math.Sign(atLimit.Y) * beyond };
            (Math.Abs((double)(over.X + over.Y)) > 1e-3 * Length(over)).Should().BeTrue($"{over} is beyond it");
            Action add = () => movers.Add(5, MoverKit.Human, p, Outdoor, over, MoverState.Creature);
            add.Should().Throw<ArgumentException>().Where(e => e.ParamName == "orientation", $"{over}");
        }

        // Taken as its turn about Z: a creature is a cylinder, met where it stands.
        movers.Add(6, MoverKit.Human, p, Outdoor, new Quaternion(Tilt, 0f, Z, W), MoverState.Creature);
        movers.Commit();
        CastHit hit = engine.Cast(At(engine, 97f, 100f) + new Vector3(0f, 0f, 1f), 0, At(engine, 103f, 100f) + new Vector3(0f, 0f, 1f), new CastOptions(0f));
        hit.Id.Should().Be(6u);
        hit.Position.X.Should().BeApproximately(p.X - MoverKit.HumanRadius, 1e-4f);
    }

    [Fact]
    public void A_mover_made_a_door_by_its_state_has_no_committed_door_state_until_the_next_commit()
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        MoverRegistry movers = engine.Movers;
        movers.Add(4, MoverKit.Human, At(engine, 100f, 100f), Outdoor, Quaternion.Identity, MoverState.Creature);
        movers.Add(5, MoverKit.Human, At(engine, 110f, 100f), Outdoor, Quaternion.Identity, MoverState.Creature with { Physics = PhysicsStateFlags.Ethereal });
        movers.Commit();
        movers.SetState(4, MoverState.Door);
        movers.SetState(5, MoverState.Door with { Physics = PhysicsStateFlags.Ethereal });
        foreach ((uint id, DoorState pending) in new[] { (4u, DoorState.Closed), (5u, DoorState.Open) })
        {
            movers.GetPendingDoorState(id).Should().Be(pending);
            Action committed = () => movers.GetDoorState(id);
            committed.Should().Throw<ArgumentException>("committed as a creature, not yet as a door").WithParameterName("doorId").WithMessage("*not yet committed*");
        }

        movers.Commit();
        movers.GetDoorState(4).Should().Be(DoorState.Closed);
        movers.GetDoorState(5).Should().Be(DoorState.Open);

        // And back: a creature again is no door at all.
        movers.SetState(4, MoverState.Creature);
        Action creature = () => movers.GetDoorState(4);
        creature.Should().Throw<ArgumentException>().WithMessage("*is not a registered door*");
    }
}
