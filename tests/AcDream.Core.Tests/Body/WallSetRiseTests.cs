using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Body;

/// <summary>
/// What a rising body's top meets overhead among the walls gathered around it (<c>WallSet.Rise</c>): an outdoor slab
/// of one polygon (a floor seen from below, no walls), the same slab standing in the east neighbour across the seam,
/// a room's ceiling, and a box's underside among more posts than the list of sources holds. The player's body
/// (radius 0.48 m, 1.835 m tall) rises 8 m in one call from the ground at 94 m; its top stops at the surface.
/// </summary>
[Trait("Mutation", "WallSet")]
public class WallSetRiseTests
{
    private const float Step = 0.6f;
    private const float Ground = 94f;
    private const float Height = 1.835f;
    private const uint Outdoor = 0xA9B40000u;
    private const uint East = 0xAAB4FFFFu;
    private const uint West = 0xA8B4FFFFu;
    private const uint Room = 0xA9B40100u;

    public static TheoryData<string> Frames => new() { "global", "centred" };

    private static PhysicsEngine Engine(string frame) => frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);

    /// <summary>A square slab of one polygon facing up, 6 m across, its centre at <paramref name="at"/> (landblock-local).</summary>
    private static ObjectSurface Slab(Vector3 at) =>
        new(ObjectKit.Gfx(0x01000101, new Vector3[] { new(-3, -3, 0), new(3, -3, 0), new(3, 3, 0), new(-3, 3, 0) }), ObjectKit.At(at, 0f), 0);

    /// <summary>The landblock-local top of a body rising 8 m from <paramref name="local"/> in <paramref name="cell"/> of Holtburg.</summary>
    private static float TopAfterRise(PhysicsEngine engine, Vector3 local, uint cell)
    {
        ResolveResult r = engine.Resolve(engine.ToWorld(Holtburg, local), cell, new Vector3(0f, 0f, 8f), Step, MovementOptions.Player);
        return engine.ToLandblockLocal(Holtburg, r.Position).Z + Height;
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_slab_overhead_stops_the_top_at_its_underside(string frame)
    {
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground), [], [Slab(new Vector3(60f, 60f, 100f))]);
        TopAfterRise(engine, new Vector3(60.5f, 59.7f, Ground), Outdoor).Should().BeApproximately(100f, 2e-3f);

        // Beside it (its edge 2.5 m from the centre): the whole rise.
        TopAfterRise(engine, new Vector3(60f, 65.5f, Ground), Outdoor).Should().BeApproximately(Ground + 8f + Height, 2e-3f);
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_slab_of_the_east_neighbour_reaching_over_the_seam_stops_the_top(string frame)
    {
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground), []);
        engine.AddLandblock(East, FlatTerrain(Ground, East), [], [Slab(new Vector3(1f, 60f, 100f))]);

        // 1.7 m west of the seam: under the slab's west part (it reaches 2 m west of the seam).
        TopAfterRise(engine, new Vector3(190.3f, 60f, Ground), Outdoor).Should().BeApproximately(100f, 2e-3f);

        // 2.6 m west of it: clear of the slab by more than the body's radius.
        TopAfterRise(engine, new Vector3(189.4f, 60f, Ground), Outdoor).Should().BeApproximately(Ground + 8f + Height, 2e-3f);
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_slab_over_part_of_the_disc_stops_the_top(string frame)
    {
        // The slab reaches x 63; the disc of a body at x 63.3 reaches back over it by 0.18 m.
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground), [], [Slab(new Vector3(60f, 60f, 100f))]);
        TopAfterRise(engine, new Vector3(63.3f, 60f, Ground), Outdoor).Should().BeApproximately(100f, 2e-3f);
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_slab_of_the_west_neighbour_reaching_over_the_seam_stops_the_top(string frame)
    {
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground), []);
        engine.AddLandblock(West, FlatTerrain(Ground, West), [], [Slab(new Vector3(191f, 60f, 100f))]);
        TopAfterRise(engine, new Vector3(1.7f, 60f, Ground), Outdoor).Should().BeApproximately(100f, 2e-3f);
        TopAfterRise(engine, new Vector3(2.6f, 60f, Ground), Outdoor).Should().BeApproximately(Ground + 8f + Height, 2e-3f);
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_box_of_the_east_neighbour_reaching_over_the_seam_stops_the_top_at_its_underside(string frame)
    {
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground), []);
        engine.AddLandblock(East, FlatTerrain(Ground, East), [], [Box(new Vector3(-1f, 58f, 97f), new Vector3(1.5f, 62f, 98f))]);
        TopAfterRise(engine, new Vector3(191.5f, 60f, Ground), Outdoor).Should().BeApproximately(97f, 2e-3f);
    }

    /// <summary>A room (x 100..120, y 100..104) with no walls, its floor at the ground, and <paramref name="more"/>.</summary>
    private static PhysicsEngine InRoom(string frame, Action<CellBuilder> more, List<ObjectSurface>? objects = null)
    {
        var builder = new CellBuilder(Room).Floor(100f, 100f, 120f, 104f, Ground);
        more(builder);
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground - 20f), [builder.Build()], objects ?? []);
        return engine;
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_rooms_own_upper_floor_stops_the_top_at_its_underside(string frame)
    {
        // A second floor 3 m up over the room's west half.
        PhysicsEngine engine = InRoom(frame, b => b.Floor(100f, 100f, 110f, 104f, Ground + 3f));
        TopAfterRise(engine, new Vector3(105f, 102f, Ground), Room).Should().BeApproximately(Ground + 3f, 2e-3f);
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void An_object_in_a_room_stops_the_top_at_its_floors_underside(string frame)
    {
        // A slab of one polygon facing up 3 m over the room's floor, standing in the room.
        var slab = new ObjectSurface(ObjectKit.Gfx(0x01000101, new Vector3[] { new(-3, -1.5f, 0), new(3, -1.5f, 0), new(3, 1.5f, 0), new(-3, 1.5f, 0) }), ObjectKit.At(new Vector3(106f, 102f, Ground + 3f), 0f), Room);
        PhysicsEngine engine = InRoom(frame, _ => { }, [slab]);
        TopAfterRise(engine, new Vector3(105f, 102f, Ground), Room).Should().BeApproximately(Ground + 3f, 2e-3f);
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void The_main_rooms_ceiling_stops_the_top_in_the_room(string frame)
    {
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground), HoltburgCells.Surfaces());
        TopAfterRise(engine, new Vector3(139.2f, 10.5f, Ground), 0xA9B40143u).Should().BeApproximately(96.8f, 2e-3f);
    }

    [Theory]
    [InlineData("global", 58f, 62f)]
    [InlineData("centred", 58f, 62f)]
    [InlineData("centred", 56f, 60.3f)]
    [InlineData("global", 60.7f, 64f)]
    public void A_boxs_underside_stops_the_top_among_more_posts_than_the_list_holds(string frame, float boxWest, float boxEast)
    {
        // 100 thin posts (r 0.02 m, 3 m tall) in the four corners of the square around the body's disc (centre
        // (60.5, 60.5)), 0.4–0.48 m from its centre along each axis: clear of the disc, in the call's box, more than the
        // 64 sources its list holds.
        var objects = new List<ObjectSurface>();
        foreach (float sx in new[] { -1f, 1f })
        {
            foreach (float sy in new[] { -1f, 1f })
            {
                for (int i = 0; i < 25; i++)
                {
                    objects.Add(Post(new Vector3(60.5f + (sx * (0.40f + (0.02f * (i % 5)))), 60.5f + (sy * (0.40f + (0.02f * (i / 5)))), Ground), 0.02f, 3f));
                }
            }
        }

        objects.Add(Box(new Vector3(boxWest, 58f, 97f), new Vector3(boxEast, 62f, 98f)));
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground), [], objects);
        TopAfterRise(engine, new Vector3(60.5f, 60.5f, Ground), Outdoor).Should().BeApproximately(97f, 2e-3f);
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_creature_overhead_stops_the_top_at_its_feet(string frame)
    {
        // A creature (r 0.48 m, 1.835 m) with its feet 3 m above the ground over the body's centre, and another 3 m away.
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground), []);
        engine.Movers.Add(2, Moving.MoverKit.Human, engine.ToWorld(Holtburg, new Vector3(60.3f, 60f, Ground + 3f)), Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Add(3, Moving.MoverKit.Human, engine.ToWorld(Holtburg, new Vector3(63.3f, 60f, Ground + 3f)), Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        TopAfterRise(engine, new Vector3(60f, 60f, Ground), Outdoor).Should().BeApproximately(Ground + 3f, 2e-3f);
        TopAfterRise(engine, new Vector3(61.8f, 60f, Ground), Outdoor).Should().BeApproximately(Ground + 8f + Height, 2e-3f, "between the two, clear of both");
    }

    private static readonly GfxObj Trunk = new() { Id = 0x01000001 };

    /// <summary>A post: a Setup of one cylinder.</summary>
    private static ObjectSurface Post(Vector3 at, float radius, float height)
    {
        var setup = new Setup { Id = 0x02000001, NumParts = 1, Parts = [Trunk.Id], CylSpheres = [new CylSphere { Origin = Vector3.Zero, Radius = radius, Height = height }] };
        return new ObjectSurface(setup, new Dictionary<uint, GfxObj> { [Trunk.Id] = Trunk }, ObjectKit.At(at, 0f), 0);
    }

    /// <summary>A closed box from <paramref name="min"/> to <paramref name="max"/> (landblock-local): four vertical sides, a top and a bottom.</summary>
    private static ObjectSurface Box(Vector3 min, Vector3 max)
    {
        (float x0, float y0, float z0, float x1, float y1, float z1) = (min.X, min.Y, min.Z, max.X, max.Y, max.Z);
        GfxObj box = ObjectKit.Gfx(0x01000002,
            [new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0)],
            [new(x0, y0, z1), new(x1, y0, z1), new(x1, y1, z1), new(x0, y1, z1)],
            Wall(x0, y0, x1, y0, z0, z1), Wall(x1, y1, x0, y1, z0, z1), Wall(x0, y1, x0, y0, z0, z1), Wall(x1, y0, x1, y1, z0, z1));
        return new ObjectSurface(box, ObjectKit.At(Vector3.Zero, 0f), 0);
    }
}
