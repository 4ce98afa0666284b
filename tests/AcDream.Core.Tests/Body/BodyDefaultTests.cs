using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Body;

/// <summary>
/// The body is free when it is off and changes nothing where it touches nothing; and its answers keep
/// the two invariants every answer keeps (issue 8): a fixed point under a zero move, and honest ground.
/// </summary>
public class BodyDefaultTests
{
    /// <summary>Hilly terrain around the real Holtburg cells (as the default-options test of the point engine), in a frame.</summary>
    private static (PhysicsEngine Engine, TerrainSurface Terrain) Holtburg(Random random, string frame)
    {
        byte[] heights = Heights((x, y) => x is >= 5 and <= 6 && y <= 1 ? 188 : random.Next(150, 200));
        var terrain = new TerrainSurface(heights, NonLinearTable(), TestData.Holtburg);
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, terrain, HoltburgCells.Surfaces());
        engine.AddLandblock(0xA9B3FFFFu, FlatTerrain(94f, 0xA9B3FFFFu), []);
        return (engine, terrain);
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void Resolve_NoBody_BitIdenticalToTheLiteralCall(string frame)
    {
        // As MovementOptionsTests.Resolve_DefaultOptions_BitIdenticalToLiteralCall, with the body named
        // and absent: 5,000 random movers outdoors and in every real cell.
        var random = new Random(5);
        (PhysicsEngine engine, _) = Holtburg(random, frame);
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        uint[] cells = [.. HoltburgCells.Fixtures.Keys];
        for (int n = 0; n < 5000; n++)
        {
            bool indoor = n % 2 == 1;
            uint cell = indoor ? cells[random.Next(cells.Length)] : 0xA9B40000u;
            var pos = origin + new Vector3(
                indoor ? 124 + (float)(random.NextDouble() * 42) : (float)(random.NextDouble() * 192),
                indoor ? -1 + (float)(random.NextDouble() * 21) : (float)(random.NextDouble() * 192),
                85 + (float)(random.NextDouble() * 60));
            var delta = new Vector3((float)(random.NextDouble() * 4) - 2, (float)(random.NextDouble() * 4) - 2, 0);
            float step = (float)(random.NextDouble() * 2);

            ResolveResult literal = engine.Resolve(pos, cell, delta, step);
            string what = $"case {n}: {pos} in 0x{cell:X8} moving {delta}, step {step}";
            engine.Resolve(pos, cell, delta, step, new MovementOptions { Body = null }).Should().Be(literal, what);
            engine.Resolve(pos, cell, delta, step, MovementOptions.Literal with { Body = null }).Should().Be(literal, what);
            engine.Resolve(pos, cell, delta, step, default).Should().Be(literal, what);
        }
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void Resolve_BodyTouchingNothing_BitIdenticalToNoBody(string frame)
    {
        // Outdoors on the hills, 25 m and more from any building, moves no longer than a sweep step: with or
        // without the player's body every effect gives the same answer, bit for bit (the body's path with no
        // contact is the point move itself; a longer swept one aims its sub-steps along the path instead).
        // Walkable slope is left out: with a body a slope too steep to climb is slid along, by design.
        var random = new Random(6);
        (PhysicsEngine engine, _) = Holtburg(random, frame);
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        MovementOptions[] configurations =
        [
            default,
            new() { StepDownHeight = 1.5f },
            new() { SweepStepLength = 0.48f },
            new() { DoorsOnly = true },
            MovementOptions.Player with { Body = null, WalkableSlope = false },
        ];
        int compared = 0;
        for (int n = 0; n < 3000; n++)
        {
            var local = new Vector2((float)(random.NextDouble() * 110), 30 + (float)(random.NextDouble() * 160));
            var pos = origin + new Vector3(local, 80 + (float)(random.NextDouble() * 80));
            double angle = random.NextDouble() * 2 * Math.PI, length = random.NextDouble() * 0.47; // within one sweep step
            var delta = new Vector3((float)(Math.Cos(angle) * length), (float)(Math.Sin(angle) * length), 0);
            float step = (float)(random.NextDouble() * 2);
            MovementOptions point = configurations[n % configurations.Length];
            ResolveResult without = engine.Resolve(pos, 0xA9B40000u, delta, step, point);
            ResolveResult with = engine.Resolve(pos, 0xA9B40000u, delta, step, point with { Body = MoverBody.Player });
            with.Should().Be(without, $"case {n}: {pos} moving {delta}, step {step}, {point}");
            compared++;
        }

        compared.Should().Be(3000);
    }

    public static TheoryData<int, string, string> Invariants() => new()
    {
        { 21, "centred", "body" }, { 21, "global", "body" }, { 22, "centred", "body + step down" }, { 22, "global", "player" },
    };

    [Theory]
    [MemberData(nameof(Invariants))]
    public void Resolve_RandomWalksWithABody_FixedPointAndHonestGround(int seed, string frame, string effects)
    {
        // Random walks on the hills around the real cells and through them (each answer the next start),
        // with a body: re-resolving an answer in place returns it bit for bit (every answer on the ground,
        // and airborne ones with step down), and IsOnGround is true exactly when the returned Z is within
        // the ground tolerance of the terrain or floor under the returned XY.
        var random = new Random(seed);
        (PhysicsEngine engine, TerrainSurface terrain) = Holtburg(random, frame);
        MovementOptions options = effects switch
        {
            "body" => new MovementOptions { Body = MoverBody.Player },
            "body + step down" => new MovementOptions { Body = MoverBody.Player, StepDownHeight = 0.75f },
            _ => MovementOptions.Player,
        };
        Vector3 origin = engine.GetLandblockOrigin(TestData.Holtburg);
        uint[] cells = [.. HoltburgCells.Fixtures.Keys];
        int answers = 0, onGround = 0, indoors = 0, touched = 0;
        for (int walk = 0; walk < 120; walk++)
        {
            bool indoor = walk % 2 == 1;
            uint cell = indoor ? cells[random.Next(cells.Length)] : 0xA9B40000u;
            CellSurface? room = indoor ? HoltburgCells.Surface(cell) : null;
            FloorTriangleInfo[] floor = room?.GetFloorTriangles() ?? [];
            if (indoor && floor.Length == 0)
            {
                (indoor, cell, room) = (false, 0xA9B40000u, null); // a shaft: start outdoors instead
            }

            Vector2 local = room is null
                ? new Vector2(120 + (float)(random.NextDouble() * 50), (float)(random.NextDouble() * 30))
                : InTriangle(floor[random.Next(floor.Length)], random);
            float ground = room is null ? terrain.SampleZ(local.X, local.Y) : room.SampleFloorZ(local.X, local.Y, 200f) ?? 94f;
            var pos = origin + new Vector3(local, ground + (float)(random.NextDouble() * 0.9) - 0.3f);
            float step = 0.3f + (float)(random.NextDouble() * 0.9);
            for (int m = 0; m < 30; m++)
            {
                var delta = new Vector3((float)(random.NextDouble() * 0.8) - 0.4f, (float)(random.NextDouble() * 0.8) - 0.4f, 0) * (random.Next(8) == 0 ? 6 : 1);
                string what = $"{frame}, {effects}, walk {walk}, move {m}: {pos:R} in 0x{cell:X8} by {delta:R}, step {step:R}";
                ResolveResult r = engine.Resolve(pos, cell, delta, step, options);
                CheckHonestGround(engine, terrain, r, what);
                if (r.IsOnGround || options.StepDownHeight is not null)
                {
                    ResolveResult again = engine.Resolve(r.Position, r.CellId, Vector3.Zero, step, options);
                    (again.Position, again.CellId, again.IsOnGround).Should().Be((r.Position, r.CellId, r.IsOnGround), $"fixed point: {what} → {r}; in place → {again}");
                }

                answers++;
                onGround += r.IsOnGround ? 1 : 0;
                indoors += CellIds.IsIndoor(r.CellId) ? 1 : 0;
                touched += r.Outcome is ResolveOutcome.Slid or ResolveOutcome.Wall ? 1 : 0;
                pos = r.IsOnGround ? r.Position : r.Position with { Z = r.Position.Z - 0.2f };
                cell = r.CellId;
            }
        }

        answers.Should().Be(120 * 30);
        onGround.Should().BeGreaterThan(answers / 2, "most answers stand on something");
        indoors.Should().BeGreaterThan(answers / 4, "a good share of answers are indoors");
        touched.Should().BeGreaterThan(answers / 20, "the body meets walls");
    }

    /// <summary>A random point of a floor triangle, pulled 5 cm towards its centre (so it is on the cell's floor).</summary>
    private static Vector2 InTriangle(FloorTriangleInfo t, Random random)
    {
        double u = random.NextDouble(), v = random.NextDouble();
        (u, v) = u + v > 1 ? (1 - u, 1 - v) : (u, v);
        var a = new Vector2(t.A.X, t.A.Y);
        Vector2 p = a + ((new Vector2(t.B.X, t.B.Y) - a) * (float)u) + ((new Vector2(t.C.X, t.C.Y) - a) * (float)v);
        Vector2 centre = (a + new Vector2(t.B.X, t.B.Y) + new Vector2(t.C.X, t.C.Y)) / 3;
        Vector2 inwards = centre - p;
        return inwards.Length() > 0.05f ? p + (Vector2.Normalize(inwards) * 0.05f) : centre;
    }

    /// <summary>IsOnGround ⟺ the returned Z is within the ground tolerance of the surface under the returned XY.</summary>
    private static void CheckHonestGround(PhysicsEngine engine, TerrainSurface terrain, ResolveResult r, string what)
    {
        float.IsFinite(r.Position.X + r.Position.Y + r.Position.Z).Should().BeTrue(what);
        Vector3 origin = engine.GetLandblockOrigin(r.CellId);
        Vector2 local = new Vector2(r.Position.X, r.Position.Y) - new Vector2(origin.X, origin.Y);
        float? ground = CellIds.IsIndoor(r.CellId)
            ? HoltburgCells.Surface(r.CellId).SampleFloorZ(local.X, local.Y, r.Position.Z)
            : (r.CellId & 0xFFFF0000u) == (TestData.Holtburg & 0xFFFF0000u) ? terrain.SampleZ(local.X, local.Y) : 94f;
        bool stands = ground is float g && MathF.Abs(r.Position.Z - g) <= PhysicsConstants.GroundTolerance;
        r.IsOnGround.Should().Be(stands, $"honest ground: {what} → {r}; ground under it {ground?.ToString("R") ?? "none"}");
    }
}
