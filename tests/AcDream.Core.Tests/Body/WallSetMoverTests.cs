using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using AcDream.Testing;

namespace AcDream.Core.Tests.Body;

/// <summary>
/// Which movers the walls gathered for a body outdoors (<c>WallSet</c>) sweep, and the shortcut that skips the plan when
/// none is touched: a door within the contact tolerance of the body, a creature wider than a metre passed beside, a
/// creature across the west seam, and a crowd of more creatures than the list of a call holds beside a hut. Flat land at
/// 50 m (landblock 0x7A3B and its west neighbour); the player's body (radius 0.48 m, 1.835 m), step 0.6 m.
/// </summary>
[Trait("Mutation", "WallSet")]
public class WallSetMoverTests
{
    private const uint Landblock = 0x7A3BFFFF, West = 0x793BFFFF;
    private const float Ground = 50f, Step = 0.6f;

    private static uint Outdoor(uint landblock, Vector3 local) =>
        (landblock & 0xFFFF0000u) | (uint)(((int)(local.X / 24f) * 8) + (int)(local.Y / 24f) + 1);

    private static PhysicsEngine Land(params ObjectSurface[] objects)
    {
        var engine = new PhysicsEngine(Landblock);
        engine.AddLandblock(Landblock, TestData.FlatTerrain(Ground, Landblock), [], objects);
        return engine;
    }

    private static void Creature(PhysicsEngine engine, uint id, Vector3 local, float radius, float height = 1.8f, uint landblock = Landblock) =>
        engine.Movers.Add(id, MoverShape.Cylinder(radius, height), engine.ToWorld(landblock, local), Outdoor(landblock, local), Quaternion.Identity, MoverState.Creature);

    private static ResolveResult Walk(PhysicsEngine engine, ResolveResult from, Vector3 delta) =>
        engine.Resolve(from.Position, from.CellId, delta, Step, MovementOptions.Player);

    /// <summary>
    /// A door (a slab 1.2 m wide, its south face at y 95.991) closed across the body's way: the body walks north into it and
    /// stops in contact, steps 0.05 mm back, then moves 0.03 mm towards it. Within the contact tolerance (0.1 mm) of the
    /// face and moving towards it, it is met at once and does not move. (The centred frame: 0.03 mm is four float steps
    /// there; the global frame's are 2 mm.)
    /// </summary>
    [Fact]
    public void A_body_within_the_contact_tolerance_of_a_door_moving_a_hair_towards_it_does_not_move()
    {
        PhysicsEngine engine = Land();
        var hinge = new Vector3(100f, 96f, Ground);
        engine.Movers.Add(9, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), engine.ToWorld(Landblock, hinge), Outdoor(Landblock, hinge), Quaternion.Identity, MoverState.Door);
        engine.Movers.Commit();
        var start = new Vector3(100f, 93f, Ground);
        ResolveResult touching = Walk(engine, new ResolveResult(engine.ToWorld(Landblock, start), Outdoor(Landblock, start), true), new Vector3(0f, 3f, 0f));
        float gap = hinge.Y + MoverReference.SlabNear - engine.ToLandblockLocal(Landblock, touching.Position).Y;
        gap.Should().BeInRange(0.48f, 0.4801f, $"stopped at its radius from the door: {touching}");

        ResolveResult back = Walk(engine, touching, new Vector3(0f, -0.00005f, 0f));
        float stepped = engine.ToLandblockLocal(Landblock, touching.Position).Y - engine.ToLandblockLocal(Landblock, back.Position).Y;
        stepped.Should().BeInRange(0.00004f, 0.00006f, $"stepped back from {touching} to {back}");

        ResolveResult hair = Walk(engine, back, new Vector3(0f, 0.00003f, 0f));
        hair.Position.Should().Be(back.Position, $"met at once, within the contact tolerance: {hair}");
    }

    /// <summary>
    /// A creature 1.5 m wide in radius, its axis 1.2 m beside the body's path: the body (0.48 m) touches it and slides
    /// round it, though the axis is more than a metre from the path.
    /// </summary>
    [Fact]
    public void A_body_passing_a_creature_wider_than_a_metre_meets_it()
    {
        PhysicsEngine engine = Land();
        Creature(engine, 2, new Vector3(100f, 96f, Ground), 1.5f);
        engine.Movers.Commit();
        var start = new Vector3(96f, 94.8f, Ground);
        ResolveResult r = Walk(engine, new ResolveResult(engine.ToWorld(Landblock, start), Outdoor(Landblock, start), true), new Vector3(3f, 0f, 0f));
        Vector3 local = engine.ToLandblockLocal(Landblock, r.Position);
        r.Outcome.Should().Be(ResolveOutcome.Slid, $"met the creature: {r}");
        local.Y.Should().BeLessThan(94.8f - 0.01f, $"pushed round it, off its straight path: {r}");
        MoverReference.Apart(local, new Vector3(100f, 96f, Ground)).Should().BeGreaterThanOrEqualTo(1.98 - 1e-3, $"never into it: {r}");
    }

    /// <summary>
    /// A creature standing just across the west seam (in the neighbour landblock's frame) stops a body walking west at
    /// their radii: the box its sweep reads is moved into the neighbour's frame.
    /// </summary>
    [Fact]
    public void A_creature_across_the_west_seam_stops_a_body_walking_west_at_their_radii()
    {
        PhysicsEngine engine = Land();
        engine.AddLandblock(West, TestData.FlatTerrain(Ground, West), []);
        var creature = new Vector3(191.7f, 96f, Ground); // 0.3 m west of the seam
        Creature(engine, 2, creature, 0.48f, landblock: West);
        engine.Movers.Commit();
        var start = new Vector3(3.5f, 96f, Ground);
        ResolveResult r = Walk(engine, new ResolveResult(engine.ToWorld(Landblock, start), Outdoor(Landblock, start), true), new Vector3(-3f, 0f, 0f));
        double apart = MoverReference.Apart(r.Position, engine.ToWorld(West, creature));
        apart.Should().BeInRange(0.96 - 1e-3, 0.97, $"stopped at their radii: {r}");
    }

    /// <summary>
    /// Seventy thin creatures (radius 1 cm) in a row 7 m long across the body's path (y 97), a hut whose south wall (y 97.3,
    /// from x 103.9) is in the box of the move just beyond them, and an object far off: more sources than the list of a call holds, so every sweep asks the grids (the
    /// hut's cell first, then the objects, then the movers). The body walking 3 m north stops at the creature on its path.
    /// </summary>
    [Fact]
    public void With_more_creatures_near_than_the_list_holds_a_body_outdoors_still_meets_the_one_on_its_path()
    {
        var hut = new CellBuilder(0x7A3B0100u)
            .Floor(103.9f, 97.3f, 108f, 101.3f, Ground)
            .Physics(TestData.Wall(103.9f, 97.3f, 108f, 97.3f, Ground, Ground + 3f))
            .Portal(0xFFFF, new Vector3(106f, 99.3f, Ground + 1f), TestData.Wall(108f, 97.3f, 108f, 101.3f, Ground, Ground + 3f));
        var far = new ObjectSurface(ObjectKit.Gfx(0x01000201, TestData.Wall(-1f, 0f, 1f, 0f, 0f, 2f)), ObjectKit.At(new Vector3(20f, 20f, Ground), 0f), 0);
        var engine = new PhysicsEngine(Landblock);
        engine.AddLandblock(Landblock, TestData.FlatTerrain(Ground, Landblock), [hut.Build()], [far]);
        for (int i = 0; i < 70; i++)
        {
            Creature(engine, 100u + (uint)i, new Vector3(100f + (0.1f * i), 97f, Ground), 0.01f);
        }

        engine.Movers.Commit();
        var start = new Vector3(103.5f, 94f, Ground);
        ResolveResult r = Walk(engine, new ResolveResult(engine.ToWorld(Landblock, start), Outdoor(Landblock, start), true), new Vector3(0f, 3f, 0f));
        Vector3 local = engine.ToLandblockLocal(Landblock, r.Position);
        local.Y.Should().BeApproximately(97f - 0.49f, 0.005f, $"stopped at the creature on its path (x 103.5): {r}");
    }
}
