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
}
