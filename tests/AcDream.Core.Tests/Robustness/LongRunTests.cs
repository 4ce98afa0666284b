using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>Long runs: no drift standing still, closed loops close, the same inputs give the same bits.</summary>
public class LongRunTests
{
    private const float GroundZ = 94f;

    /// <summary>Holtburg's cells on gentle hills around the cottage (flat at 94 m around the buildings), and its neighbours.</summary>
    private static PhysicsEngine Holtburg(PhysicsEngine engine)
    {
        byte[] heights = Heights((x, y) => x is >= 5 and <= 7 && y <= 1 ? 188 : 186 + ((x + y) % 3));
        float[] table = Enumerable.Range(0, 256).Select(i => 0.5f * i).ToArray(); // 188 → 94 m
        engine.AddLandblock(TestData.Holtburg, new TerrainSurface(heights, table, TestData.Holtburg), HoltburgCells.Surfaces());
        engine.AddLandblock(0xA9B3FFFFu, new TerrainSurface(FlatHeights(188), table, 0xA9B3FFFFu), []);
        return engine;
    }

    public static TheoryData<string, Vector3, uint> StandingPlaces() => new()
    {
        { "hillside", new Vector3(30.3f, 100.7f, 95f), 0xA9B40000u },
        { "on the x seam with the west id", new Vector3(192f, 100.7f, 95f), 0xA9B40039u },
        { "on a terrain diagonal", new Vector3(48f + 7.125f, 72f + 7.125f, 95f), 0xA9B40000u },
        { "cottage main room", new Vector3(138.5f, 10f, GroundZ), 0xA9B40143u },
        { "cellar past the south seam", new Vector3(141f, -0.5f, 90.95f), 0xA9B40147u },
        { "in the floorless shaft", new Vector3(141.3f, 6f, 93f), 0xA9B40146u },
    };

    [Theory]
    [MemberData(nameof(StandingPlaces))]
    public void Resolve_Standing100000Frames_NoDrift(string place, Vector3 start, uint cell)
    {
        foreach (bool global in new[] { false, true })
        {
            PhysicsEngine engine = Holtburg(global ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg));
            Vector3 offset = engine.GetLandblockOrigin(TestData.Holtburg);
            ResolveResult first = engine.Resolve(start + offset, cell, Vector3.Zero, 0.5f);
            ResolveResult r = first;
            for (int frame = 0; frame < 100_000; frame++)
            {
                r = engine.Resolve(r.Position, r.CellId, Vector3.Zero, 0.5f);
                if (r != first)
                {
                    r.Should().Be(first, $"{place} ({(global ? "global" : "centred")}): frame {frame} drifted");
                }
            }

            (first.Position.X - offset.X).Should().BeApproximately(start.X, 4e-3f, place);
        }
    }

    /// <summary>
    /// Walks a closed polygon of waypoints with deltas fixed in advance (the caller's input), about
    /// 0.133 m per frame (4 m/s at 30 fps), summing to zero in exact arithmetic. Every frame must be
    /// accepted and on the ground. Returns the start, the end, the frames and the cells visited.
    /// </summary>
    private static (Vector3 Start, ResolveResult End, int Frames, HashSet<uint> Cells) WalkLoop(PhysicsEngine engine, Vector2[] waypoints)
    {
        Vector3 offset = engine.GetLandblockOrigin(TestData.Holtburg);
        var deltas = new List<Vector3>();
        for (int i = 0; i + 1 < waypoints.Length; i++)
        {
            Vector2 leg = waypoints[i + 1] - waypoints[i];
            int frames = (int)MathF.Ceiling(leg.Length() / 0.133f);
            for (int f = 0; f < frames; f++)
            {
                deltas.Add(new Vector3(leg / frames, 0));
            }
        }

        ResolveResult r = engine.Resolve(new Vector3(offset.X + waypoints[0].X, offset.Y + waypoints[0].Y, GroundZ), 0xA9B40000u, Vector3.Zero, 0.6f);
        Vector3 start = r.Position;
        var cells = new HashSet<uint>();
        for (int i = 0; i < deltas.Count; i++)
        {
            ResolveResult next = engine.Resolve(r.Position, r.CellId, deltas[i], 0.6f);
            next.Position.Should().NotBe(r.Position, $"frame {i} from {r.Position:R} in 0x{r.CellId:X8} by {deltas[i]:R} must be accepted");
            next.IsOnGround.Should().BeTrue($"frame {i}");
            cells.Add(next.CellId & 0xFFFF);
            r = next;
        }

        return (start, r, deltas.Count, cells);
    }

    [Fact]
    public void Resolve_ClosedLoopThroughTheCottage_ReturnsWithin1mm()
    {
        // In at the west door, across the main room to the doorway 0x0144 and back, out of the door,
        // and round a patch of ground west of the cottage back to the start.
        PhysicsEngine engine = Holtburg(new PhysicsEngine(TestData.Holtburg));
        (Vector3 start, ResolveResult end, int frames, HashSet<uint> cells) = WalkLoop(engine,
        [
            new(134.0f, 5.15f), new(138.5f, 5.15f), new(138.5f, 10f), new(136.5f, 10f), new(138.5f, 10f), new(138.5f, 5.15f),
            new(134.0f, 5.15f), new(130f, 5.15f), new(130f, 1f), new(134f, 1f), new(134.0f, 5.15f),
        ]);

        cells.Should().Contain([0x0145u, 0x0143u, 0x0144u], "the loop passes through the cottage");
        Vector3.Distance(end.Position, start).Should().BeLessThan(1e-3f, $"{frames} frames: start {start:R}, end {end.Position:R}");
        end.CellId.Should().Be(engine.Resolve(start, 0xA9B40000u, Vector3.Zero, 0.6f).CellId);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void Resolve_LongClosedLoopOnHills_ErrorBoundedByOneRoundingPerFrame(bool global)
    {
        // 1,200+ frames over the hills. Each frame rounds the position once (to the float spacing at
        // its magnitude), so the closure error is bounded by frames × half that spacing: 7.6e-6 m per
        // frame landblock-locally (centred frame), 2 mm per frame in the global frame at Holtburg.
        PhysicsEngine engine = Holtburg(global ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg));
        Vector3 offset = engine.GetLandblockOrigin(TestData.Holtburg);
        (Vector3 start, ResolveResult end, int frames, _) = WalkLoop(engine, [new(100f, 40f), new(60f, 60f), new(40f, 20f), new(90f, 20f), new(100f, 40f)]);

        float magnitude = MathF.Max(MathF.Abs(offset.X), MathF.Abs(offset.Y)) + 128f;
        float halfSpacing = 0.5f * (MathF.BitIncrement(magnitude) - magnitude);
        float error = Vector3.Distance(end.Position, start);
        frames.Should().BeGreaterThan(1200);
        error.Should().BeLessThanOrEqualTo(frames * halfSpacing * 1.5f, $"{frames} frames, {(global ? "global" : "centred")}: start {start:R}, end {end.Position:R}");
        if (!global)
        {
            error.Should().BeLessThan(0.01f, "landblock-locally the bound is under a centimetre for this loop");
        }
    }

    [Fact]
    public void Resolve_LongRandomRun_BitIdenticalAcrossEnginesAndHistories()
    {
        // 30,000 frames of a seeded random walk through hills and the Holtburg cells, hashed bit for
        // bit; replayed on a fresh engine, and on one that first registered, removed and re-registered
        // landblocks and answered unrelated queries.
        ulong first = Run(Holtburg(new PhysicsEngine(TestData.Holtburg)));
        ulong again = Run(Holtburg(new PhysicsEngine(TestData.Holtburg)));

        PhysicsEngine busy = Holtburg(new PhysicsEngine(TestData.Holtburg));
        busy.AddLandblock(0xAAB4FFFFu, FlatTerrain(3f, 0xAAB4FFFFu), []);
        busy.RemoveLandblock(0xAAB4FFFFu);
        busy.RemoveLandblock(TestData.Holtburg);
        Holtburg(busy);
        for (int i = 0; i < 1000; i++)
        {
            busy.Resolve(new Vector3(i % 192, i / 7f, 50), 0, new Vector3(0.3f, -0.2f, 0), 1f);
        }

        ulong busyHash = Run(busy);

        again.Should().Be(first, "the same inputs give bit-identical outputs");
        busyHash.Should().Be(first, "Resolve is a pure function of what is registered: history does not matter");

        static ulong Run(PhysicsEngine engine)
        {
            var random = new Random(77);
            ulong hash = 14695981039346656037ul; // FNV-1a over the raw bits
            void Mix(uint bits)
            {
                for (int b = 0; b < 4; b++)
                {
                    hash = (hash ^ ((bits >> (8 * b)) & 0xFF)) * 1099511628211ul;
                }
            }

            var pos = new Vector3(134.0f, 5.15f, GroundZ);
            uint cell = 0xA9B40000u;
            var heading = new Vector2(1, 0);
            for (int frame = 0; frame < 30_000; frame++)
            {
                float turn = Gen.Range(random, -0.4, 0.4);
                heading = Vector2.Transform(heading, Matrix3x2.CreateRotation(turn));
                if (Vector2.Distance(new Vector2(pos.X, pos.Y), new Vector2(138, 8)) > 40)
                {
                    heading = Vector2.Normalize(new Vector2(138, 8) - new Vector2(pos.X, pos.Y));
                }

                ResolveResult r = engine.Resolve(pos, cell, new Vector3(heading * Gen.Range(random, 0, 0.3), 0), 0.5f);
                Mix(BitConverter.SingleToUInt32Bits(r.Position.X));
                Mix(BitConverter.SingleToUInt32Bits(r.Position.Y));
                Mix(BitConverter.SingleToUInt32Bits(r.Position.Z));
                Mix(r.CellId);
                Mix(r.IsOnGround ? 1u : 0u);
                (pos, cell) = (r.IsOnGround ? r.Position : r.Position with { Z = r.Position.Z - 0.1f }, r.CellId);
            }

            return hash;
        }
    }
}
