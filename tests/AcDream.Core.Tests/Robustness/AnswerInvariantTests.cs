using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// The two invariants every answer keeps (issue 8), on seeded random worlds in both world frames
/// (global, centred on the landblock, centred on the opposite corner of the world), with landblocks
/// at the world's corners and edges, random terrain and random rotated cells, with and without options:
/// <list type="bullet">
/// <item>Fixed point: re-resolving an answer in place (zero delta) returns it bit for bit, for every
/// answer on the ground, and for airborne ones when step down is on (the literal engine puts any
/// accepted move on the ground, so its airborne refusals are the one exception).</item>
/// <item>Honest ground: <c>IsOnGround</c> is true exactly when the returned Z is within
/// <see cref="PhysicsConstants.GroundTolerance"/> of the terrain or floor under the returned XY.</item>
/// </list>
/// Each world's movers walk chains of moves (each answer is the next start), as a frame loop does.
/// </summary>
public class AnswerInvariantTests
{
    public static TheoryData<int, string> Cases() => new()
    {
        { 11, "literal" }, { 11, "step down" }, { 11, "player" },
        { 12, "literal" }, { 12, "step down" }, { 12, "player" },
        { 102, "footing" }, { 106, "footing" }, // footing on stepped floors, raised on from tread to tread
    };

    private static MovementOptions Options(string name) => name switch
    {
        "literal" => MovementOptions.Literal,
        "step down" => new MovementOptions { StepDownHeight = 0.75f },
        "footing" => MovementOptions.Player with { Vertical = false },
        _ => MovementOptions.Player,
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void Resolve_RandomWalksInRandomWorlds_FixedPointAndHonestGround(int seed, string effects)
    {
        MovementOptions options = Options(effects);
        var random = new Random(seed);
        int checkedAnswers = 0, onGround = 0, airborne = 0, indoors = 0;
        for (int w = 0; w < 9; w++)
        {
            int lbX = random.Next(3) switch { 0 => 0x00, 1 => 0xFE, _ => random.Next(1, 254) };
            int lbY = random.Next(3) switch { 0 => 0x00, 1 => 0xFE, _ => random.Next(1, 254) };
            uint id = ((uint)lbX << 24) | ((uint)lbY << 16) | 0xFFFFu;
            uint far = ((uint)(0xFE - lbX) << 24) | ((uint)(0xFE - lbY) << 16) | 0xFFFFu;
            string frame = (w % 3) switch { 0 => "global", 1 => "centred here", _ => "centred far" };
            var engine = frame switch { "global" => new PhysicsEngine(), "centred here" => new PhysicsEngine(id), _ => new PhysicsEngine(far) };
            var terrain = new TerrainSurface(Gen.Heights(random), Gen.HeightTable(random), id);
            List<CellSurface> cells = RandomRooms(random, id, terrain);
            engine.AddLandblock(id, terrain, cells);
            Vector3 offset = engine.GetLandblockOrigin(id);

            for (int walk = 0; walk < 60; walk++)
            {
                bool indoor = walk % 2 == 1;
                CellSurface? room = indoor ? cells[random.Next(cells.Count)] : null;
                Vector2 local = room is null
                    ? new Vector2(Gen.Range(random, 0, 192), Gen.Range(random, 0, 192))
                    : new Vector2(room.Origin.X, room.Origin.Y) + new Vector2(Gen.Range(random, -4, 4), Gen.Range(random, -4, 4));
                float ground = room is null ? terrain.SampleZ(local.X, local.Y) : room.SampleFloorZ(local.X, local.Y, room.Origin.Z) ?? room.Origin.Z;
                var pos = new Vector3(offset.X + local.X, offset.Y + local.Y, ground + Gen.Range(random, -0.3, 0.6));
                uint cell = room?.CellId ?? (id & 0xFFFF0000u);
                float step = Gen.Range(random, 0.2, 1.2);
                bool onGroundBefore = true;
                for (int m = 0; m < 40; m++)
                {
                    // Mostly walking-sized moves, some long; a fifth of them aimed at a room's wall edge.
                    var delta = new Vector3(Gen.Range(random, -0.5, 0.5), Gen.Range(random, -0.5, 0.5), 0) * (random.Next(8) == 0 ? 12 : 1);
                    if (options.Vertical)
                    {
                        // The body moves up and down itself: a fall in the air, now and then a jump.
                        delta.Z = !onGroundBefore ? -1f : random.Next(10) == 0 ? 0.3f : 0f;
                    }

                    string what = $"seed {seed}, {effects}, world {w} (0x{id:X8}, {frame}), walk {walk}, move {m}: {pos:R} in 0x{cell:X8} by {delta:R}, step {step:R}";
                    ResolveResult r = engine.Resolve(pos, cell, delta, step, options);
                    CheckHonestGround(engine, terrain, cells, r, what, options);
                    bool stable = r.IsOnGround || options.StepDownHeight is not null;
                    if (stable)
                    {
                        ResolveResult again = engine.Resolve(r.Position, r.CellId, Vector3.Zero, step, options);
                        (again.Position, again.CellId, again.IsOnGround).Should().Be((r.Position, r.CellId, r.IsOnGround), $"fixed point: {what} → {r}; in place → {again}");
                    }

                    checkedAnswers++;
                    onGround += r.IsOnGround ? 1 : 0;
                    airborne += r.IsOnGround ? 0 : 1;
                    indoors += (r.CellId & 0xFFFF) >= 0x100 ? 1 : 0;

                    // Keep walking from the answer; a mover in mid-air drops a little, as under gravity (the body with vertical
                    // motion by its next delta).
                    pos = r.IsOnGround || options.Vertical ? r.Position : r.Position with { Z = r.Position.Z - 0.2f };
                    onGroundBefore = r.IsOnGround;
                    cell = r.CellId;
                }
            }
        }

        checkedAnswers.Should().Be(9 * 60 * 40);
        onGround.Should().BeGreaterThan(checkedAnswers / 2, "most answers stand on something");
        airborne.Should().BeGreaterThan(0, "some answers are in mid-air");
        indoors.Should().BeGreaterThan(checkedAnswers / 5, "a good share of answers are indoors");
    }

    /// <summary>IsOnGround ⟺ the returned Z is within the ground tolerance of the surface under the returned XY.</summary>
    private static void CheckHonestGround(PhysicsEngine engine, TerrainSurface terrain, List<CellSurface> cells, ResolveResult r, string what, MovementOptions options)
    {
        float.IsFinite(r.Position.X + r.Position.Y + r.Position.Z).Should().BeTrue(what);
        Vector3 origin = engine.GetLandblockOrigin(r.CellId);
        Vector2 local = new Vector2(r.Position.X, r.Position.Y) - new Vector2(origin.X, origin.Y);
        float? ground = (r.CellId & 0xFFFF) < 0x100
            ? terrain.SampleZ(local.X, local.Y)
            : cells.Single(c => c.CellId == r.CellId).SampleFloorZ(local.X, local.Y, r.Position.Z);
        bool stands = (ground is float g && MathF.Abs(r.Position.Z - g) <= PhysicsConstants.GroundTolerance)
            || FootingReference.HoldsAnswer(options, cells, [], r, local);
        r.IsOnGround.Should().Be(stands, $"honest ground: {what} → {r}; ground under it {ground?.ToString("R") ?? "none"}");
    }

    /// <summary>
    /// Five rooms with random rotation (some sloppy quaternions), each a 6 × 6 floor (sometimes sloped
    /// or stepped), walls, and a doorway to the outdoors in its west wall; and one with random polygons.
    /// </summary>
    private static List<CellSurface> RandomRooms(Random random, uint id, TerrainSurface terrain)
    {
        var cells = new List<CellSurface>();
        for (int c = 0; c < 6; c++)
        {
            var at = new Vector2(Gen.Range(random, 12, 180), Gen.Range(random, 12, 180));
            var origin = new Vector3(at, terrain.SampleZ(at.X, at.Y) + Gen.Range(random, -0.4, 0.4));
            var builder = new CellBuilder((id & 0xFFFF0000u) | (uint)(0x0100 + c), origin, Gen.Orientation(random, sloppy: random.Next(2) == 0));
            if (c == 5)
            {
                for (int p = random.Next(2, 7); p > 0; p--)
                {
                    builder.Physics(Gen.Polygon(random, 4));
                }
            }
            else
            {
                float tilt = random.Next(3) == 0 ? Gen.Range(random, -0.3, 0.3) : 0f;
                builder.Physics(new Vector3(-3, -3, -3 * tilt), new Vector3(3, -3, 3 * tilt), new Vector3(3, 3, 3 * tilt), new Vector3(-3, 3, -3 * tilt));
                if (random.Next(2) == 0)
                {
                    builder.Floor(0, -3, 3, 3, 0.3f); // a raised half: a step inside the room
                }

                builder.Physics(Wall(3, -3, 3, 3, -1, 3)).Physics(Wall(3, 3, -3, 3, -1, 3)).Physics(Wall(-3, -3, 3, -3, -1, 3));
            }

            builder.Portal(0xFFFF, new Vector3(0, 0, 1), Wall(-3, 1, -3, -1, -1, 2.5f));
            cells.Add(builder.Build());
        }

        return cells;
    }
}
