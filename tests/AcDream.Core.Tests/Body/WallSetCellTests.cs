using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Body;

/// <summary>
/// Which sources the walls gathered for a body inside a cell (<c>WallSet</c>) hold: the landblock's first cell (index
/// 0) reached through a doorway from the next, and no outdoor object for a body in the first cell. Two rooms of Holtburg
/// side by side (0x0100 over x 100..104, 0x0101 over x 104..108, y 100..104, floors at 94 m) joined by a doorway as wide
/// as they are; the player's body (radius 0.48 m, 1.835 m), step 0.6 m.
/// </summary>
[Trait("Mutation", "WallSet")]
public class WallSetCellTests
{
    private const float Ground = 94f;
    private const float Step = 0.6f;
    private const float Height = 1.835f;
    private const uint First = 0xA9B40100u;
    private const uint Second = 0xA9B40101u;

    public static TheoryData<string> Frames => new() { "global", "centred" };

    private static PhysicsEngine Rooms(string frame, Action<CellBuilder> first, ObjectSurface[]? outdoors = null, Action<CellBuilder>? second = null)
    {
        var a = new CellBuilder(First).Floor(100f, 100f, 104f, 104f, Ground)
            .Portal(0x0101, new Vector3(102f, 102f, Ground + 1f), Wall(104f, 100f, 104f, 104f, Ground, Ground + 3f));
        first(a);
        var b = new CellBuilder(Second).Floor(104f, 100f, 108f, 104f, Ground)
            .Portal(0x0100, new Vector3(106f, 102f, Ground + 1f), Wall(104f, 104f, 104f, 100f, Ground, Ground + 3f));
        second?.Invoke(b);
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground - 20f), [a.Build(), b.Build()], outdoors ?? []);
        return engine;
    }

    /// <summary>
    /// A wall across the first room at x 102 (its own wall, facing the doorway): a body in the second room walking 4 m
    /// west through the doorway stops at its radius from that wall, in the first room.
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void A_body_walking_into_the_first_cell_of_the_landblock_meets_its_wall(string frame)
    {
        PhysicsEngine engine = Rooms(frame, a => a.Physics(new(102f, 104f, Ground), new(102f, 100f, Ground), new(102f, 100f, Ground + 3f), new(102f, 104f, Ground + 3f)));
        ResolveResult r = engine.Resolve(engine.ToWorld(Holtburg, new Vector3(106f, 102f, Ground)), Second, new Vector3(-4f, 0f, 0f), Step, MovementOptions.Player);
        Vector3 local = engine.ToLandblockLocal(Holtburg, r.Position);
        local.X.Should().BeApproximately(102.48f, 0.01f, $"{frame}: stopped at its radius from the first room's wall: {r}");
        r.CellId.Should().Be(First, $"{frame}: {r}");
    }

    /// <summary>
    /// An outdoor slab (one polygon facing up, no walls) 6 m above the first room's floor, over it, and the room's ceiling
    /// 9 m up: a body rising 8 m in the room beside the doorway stops its top at the ceiling (indoors the cells and what stands in them are
    /// the walls, not the outdoor objects), while outdoors beside the building the slab stops the top at its underside.
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void A_body_rising_in_the_first_cell_of_the_landblock_does_not_meet_an_outdoor_slab_over_it(string frame)
    {
        var slab = new ObjectSurface(ObjectKit.Gfx(0x01000101, new Vector3[] { new(-5, -3, 0), new(5, -3, 0), new(5, 3, 0), new(-5, 3, 0) }), ObjectKit.At(new Vector3(102f, 102f, Ground + 6f), 0f), 0);
        PhysicsEngine engine = Rooms(frame, a => a.Physics(new(100f, 100f, Ground + 9f), new(100f, 104f, Ground + 9f), new(104f, 104f, Ground + 9f), new(104f, 100f, Ground + 9f)), [slab]);
        ResolveResult inside = engine.Resolve(engine.ToWorld(Holtburg, new Vector3(103.6f, 102f, Ground)), First, new Vector3(0f, 0f, 8f), Step, MovementOptions.Player);
        (engine.ToLandblockLocal(Holtburg, inside.Position).Z + Height).Should().BeApproximately(Ground + 9f, 2e-3f, $"{frame}: in the room, at its ceiling: {inside}");

        ResolveResult outside = engine.Resolve(engine.ToWorld(Holtburg, new Vector3(98f, 102f, Ground - 20f)), 0xA9B40000u, new Vector3(0f, 0f, 25f), Step, MovementOptions.Player);
        (engine.ToLandblockLocal(Holtburg, outside.Position).Z + Height).Should().BeApproximately(Ground + 6f, 2e-3f, $"{frame}: outdoors under the slab: {outside}");
    }
    /// <summary>
    /// Seventy thin creatures (radius 1 cm) standing just behind the body's shoulders, in the box of its move but clear
    /// of its path: more sources than the list of a call holds, so every sweep asks the grids (the cells of the body's
    /// building, then the movers). The body walking 4 m east from the first room through the doorway into the second
    /// room's east wall (its own wall at x 107) stops at its radius from it.
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void With_more_movers_near_than_the_list_holds_a_body_indoors_still_meets_the_walls_of_its_building(string frame)
    {
        PhysicsEngine engine = Rooms(frame, _ => { }, second: b => b.Physics(new(107f, 100f, Ground), new(107f, 104f, Ground), new(107f, 104f, Ground + 3f), new(107f, 100f, Ground + 3f)));
        var start = new Vector3(102f, 102f, Ground);
        for (int i = 0; i < 70; i++)
        {
            float side = i % 2 == 0 ? 0.46f : -0.46f;
            Vector3 at = engine.ToWorld(Holtburg, start + new Vector3(-0.46f + (0.001f * (i / 2)), side, 0f));
            engine.Movers.Add(100u + (uint)i, MoverShape.Cylinder(0.01f, 1f), at, First, Quaternion.Identity, MoverState.Creature);
        }

        engine.Movers.Commit();
        ResolveResult r = engine.Resolve(engine.ToWorld(Holtburg, start), First, new Vector3(6f, 0f, 0f), Step, MovementOptions.Player);
        Vector3 local = engine.ToLandblockLocal(Holtburg, r.Position);
        local.X.Should().BeApproximately(106.52f, 0.01f, $"{frame}: stopped at its radius from the second room's east wall: {r}");
        r.CellId.Should().Be(Second, $"{frame}: {r}");
    }
}
