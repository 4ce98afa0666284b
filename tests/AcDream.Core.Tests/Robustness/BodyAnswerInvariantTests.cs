using AcDream.Testing;
using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// With a body, answers keep the two invariants every answer keeps (issue 8): a fixed point under a zero
/// move, and honest ground. Random walks on hills around the real Holtburg cells and through them.
/// </summary>
public class BodyAnswerInvariantTests
{
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
        (PhysicsEngine engine, TerrainSurface terrain) = HoltburgCells.OnHills(random, frame);
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
            bool onGroundBefore = true;
            for (int m = 0; m < 30; m++)
            {
                var delta = new Vector3((float)(random.NextDouble() * 0.8) - 0.4f, (float)(random.NextDouble() * 0.8) - 0.4f, 0) * (random.Next(8) == 0 ? 6 : 1);
                if (options.Vertical)
                {
                    delta.Z = !onGroundBefore ? -1f : random.Next(10) == 0 ? 0.3f : 0f; // the body falls and jumps by its delta
                }

                string what = $"{frame}, {effects}, walk {walk}, move {m}: {pos:R} in 0x{cell:X8} by {delta:R}, step {step:R}";
                ResolveResult r = engine.Resolve(pos, cell, delta, step, options);
                CheckHonestGround(engine, terrain, r, what, options);
                if (r.IsOnGround || options.StepDownHeight is not null)
                {
                    ResolveResult again = engine.Resolve(r.Position, r.CellId, Vector3.Zero, step, options);
                    (again.Position, again.CellId, again.IsOnGround).Should().Be((r.Position, r.CellId, r.IsOnGround), $"fixed point: {what} → {r}; in place → {again}");
                }

                answers++;
                onGround += r.IsOnGround ? 1 : 0;
                indoors += CellIds.IsIndoor(r.CellId) ? 1 : 0;
                touched += r.Outcome is ResolveOutcome.Slid or ResolveOutcome.Wall ? 1 : 0;
                pos = r.IsOnGround || options.Vertical ? r.Position : r.Position with { Z = r.Position.Z - 0.2f };
                cell = r.CellId;
                onGroundBefore = r.IsOnGround;
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
    private static void CheckHonestGround(PhysicsEngine engine, TerrainSurface terrain, ResolveResult r, string what, MovementOptions options)
    {
        float.IsFinite(r.Position.X + r.Position.Y + r.Position.Z).Should().BeTrue(what);
        Vector3 origin = engine.GetLandblockOrigin(r.CellId);
        Vector2 local = new Vector2(r.Position.X, r.Position.Y) - new Vector2(origin.X, origin.Y);
        float? ground = CellIds.IsIndoor(r.CellId)
            ? HoltburgCells.Surface(r.CellId).SampleFloorZ(local.X, local.Y, r.Position.Z)
            : (r.CellId & 0xFFFF0000u) == (TestData.Holtburg & 0xFFFF0000u) ? terrain.SampleZ(local.X, local.Y) : 94f;
        bool stands = (ground is float g && MathF.Abs(r.Position.Z - g) <= PhysicsConstants.GroundTolerance)
            || FootingReference.HoldsAnswer(options, CellIds.IsIndoor(r.CellId) ? [HoltburgCells.Surface(r.CellId)] : [], [], r, local);
        r.IsOnGround.Should().Be(stands, $"honest ground: {what} → {r}; ground under it {ground?.ToString("R") ?? "none"}");
    }
}
