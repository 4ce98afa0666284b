using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// A move that climbs the terrain ends where an object's floor is within a step of its new feet but
/// more than a step above the feet it set out with. The answer must be a fixed point with honest ground:
/// measured from where it ends, that floor is within reach, so the move ends on it or is refused, never
/// under it (a slide beside a building on a plinth ended 0.3 m below the plinth's top, and resolving
/// there again climbed onto it).
/// </summary>
[Trait("Mutation", "ObjectQueries")]
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class GroundAtRestTests
{
    private const uint Landblock = 0xFDFDFFFFu;

    /// <summary>Terrain rising 1 m per 24 m eastward; a platform (a floor polygon alone, no walls) over x 40..44 at <paramref name="platformZ"/>.</summary>
    private static PhysicsEngine Engine(string frame, float platformZ)
    {
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(0x0101FFFFu);
        var table = new float[256];
        for (int i = 0; i < 256; i++)
        {
            table[i] = 40f + i;
        }

        var terrain = new TerrainSurface(TestData.Heights((x, _) => x), table, Landblock);
        GfxObj platform = ObjectKit.Gfx(0x01000400, TestData.Square(40f, 40f, 44f, 44f, platformZ));
        engine.AddLandblock(Landblock, terrain, [], [new ObjectSurface(platform, ObjectKit.At(Vector3.Zero, 0f), 0)]);
        return engine;
    }

    public static TheoryData<string, string> Cases() => new()
    {
        { "global", "literal" }, { "global", "body" }, { "global", "Player" },
        { "centred", "literal" }, { "centred", "body" }, { "centred", "Player" },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void A_move_that_climbs_the_terrain_ends_on_a_floor_its_end_reaches_or_is_refused(string frame, string effects)
    {
        // From x 28 (terrain 41.1667) east by 14 m to x 42 (terrain 41.75): a rise of 0.583, within the step of
        // 0.6. The platform at 42.1 is 0.35 m above the terrain there, 0.93 m above the start.
        MovementOptions options = effects switch
        {
            "literal" => MovementOptions.Literal,
            "body" => new MovementOptions { Body = MoverBody.Player },
            _ => MovementOptions.Player,
        };
        PhysicsEngine engine = Engine(frame, 42.1f);
        Vector3 origin = engine.GetLandblockOrigin(Landblock);
        const float step = 0.6f;
        var start = new Vector3(28f, 42f, 0f) + origin;
        start.Z = engine.Resolve(start, Landblock & 0xFFFF0000, Vector3.Zero, step).Position.Z;
        ResolveResult r = engine.Resolve(start, Landblock & 0xFFFF0000, new Vector3(14f, 0f, 0f), step, options);
        ResolveResult again = engine.Resolve(r.Position, r.CellId, Vector3.Zero, step, options);
        engine.TryGetGround(r.Position, r.CellId, step, out float ground, out _, out uint objectId).Should().BeTrue();
        string what = $"{frame}, {effects}: from {start - origin:R} → {r} (local {r.Position - origin:R}); in place → {again}; ground {ground:R} (object 0x{objectId:X8})";
        (again.Position, again.CellId, again.IsOnGround).Should().Be((r.Position, r.CellId, r.IsOnGround), $"fixed point: {what}");
        r.IsOnGround.Should().Be(MathF.Abs(r.Position.Z - ground) <= PhysicsConstants.GroundTolerance, $"honest ground: {what}");
        (r.Position.Z < 42.1f - 0.01f && r.Position.X - origin.X >= 40f && r.Position.X - origin.X <= 44f).Should().BeFalse($"not under the platform: {what}");
    }

    [Theory]
    [InlineData("global")]
    [InlineData("centred")]
    public void Standing_under_a_floor_within_a_step_of_the_feet_is_lifted_onto_it_and_stays(string frame)
    {
        PhysicsEngine engine = Engine(frame, 42.1f);
        Vector3 origin = engine.GetLandblockOrigin(Landblock);
        var under = new Vector3(42f, 42f, 41.75f) + origin; // on the terrain, 0.35 m below the platform
        ResolveResult r = engine.Resolve(under, Landblock & 0xFFFF0000, Vector3.Zero, 0.6f);
        r.Position.Z.Should().Be(42.1f, $"{frame}: {r}");
        engine.Resolve(r.Position, r.CellId, Vector3.Zero, 0.6f).Should().Be(r);
    }
    [Theory]
    [InlineData("global")]
    [InlineData("centred")]
    public void The_ground_under_stacked_floors_is_reached_a_step_at_a_time_and_stays(string frame)
    {
        // Flat terrain at 94 m; four floors (polygons alone, each its own object) over the same square at
        // 94.4, 94.8, 95.2 and 95.8 m. With a step of 0.5 m from feet at 94 m each of the first three is within
        // a step of the one below; the fourth is 0.6 m above the third.
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        float[] levels = [94.4f, 94.8f, 95.2f, 95.8f];
        var floors = new List<ObjectSurface>();
        for (int k = 0; k < levels.Length; k++)
        {
            GfxObj gfx = ObjectKit.Gfx(0x01000500u + (uint)k, TestData.Square(60f, 60f, 64f, 64f, levels[k]));
            floors.Add(new ObjectSurface(gfx, ObjectKit.At(Vector3.Zero, 0f), 0));
        }

        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), [], floors);
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        const uint outdoors = TestData.Holtburg & 0xFFFF0000;
        foreach (float feet in new[] { 94f, 94.4f, 94.8f, 95.2f })
        {
            engine.TryGetGround(origin + new Vector3(62f, 62f, feet), outdoors, 0.5f, out float ground, out _, out uint objectId).Should().BeTrue();
            ground.Should().Be(95.2f, $"{frame}: feet at {feet} m reach the third floor a step at a time, not the fourth");
            objectId.Should().Be(0x01000502u, $"{frame}: feet at {feet} m");
        }

        engine.TryGetGround(origin + new Vector3(62f, 62f, 95.4f), outdoors, 0.5f, out float top, out _, out uint topId).Should().BeTrue();
        (top, topId).Should().Be((95.8f, 0x01000503u), $"{frame}: feet 0.4 m below the fourth floor reach it");
        engine.TryGetGround(origin + new Vector3(70f, 62f, 94f), outdoors, 0.5f, out float beside, out _, out uint none).Should().BeTrue();
        (beside, none).Should().Be((94f, 0u), $"{frame}: beside the stack the ground is the terrain");
    }
}
