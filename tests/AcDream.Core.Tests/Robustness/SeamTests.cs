using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Points exactly on seams (shared triangle edges and vertices, terrain cell edges and diagonals,
/// landblock seams) and one float step either side: always a surface, Z continuous.
/// </summary>
public class SeamTests
{
    private const uint West = 0x7F40FFFFu;
    private const uint East = 0x8040FFFFu;

    /// <summary>Two neighbouring landblocks of random hills sharing their seam column (x = 8 of West is x = 0 of East).</summary>
    private static (TerrainSurface West, TerrainSurface East, double Gradient) SeamPair(int seed, uint west = West, uint east = East)
    {
        var random = new Random(seed);
        byte[] w = Gen.Heights(random), e = Gen.Heights(random);
        for (int y = 0; y < 9; y++)
        {
            e[y] = w[(8 * 9) + y];
        }

        float[] table = NonLinearTable();
        return (new TerrainSurface(w, table, west), new TerrainSurface(e, table, east), Math.Max(Reference.MaxGradient(w, table), Reference.MaxGradient(e, table)));
    }

    [Theory]
    [InlineData(1)]
    [InlineData(2)]
    [InlineData(3)]
    public void SampleZ_OnLandblockSeamAndOneFloatStepEitherSide_ContinuousWithin1e4(int seed)
    {
        (TerrainSurface west, TerrainSurface east, double gradient) = SeamPair(seed);
        for (float y = 0f; y <= 192f; y += 0.375f)
        {
            float onSeamWest = west.SampleZ(192f, y), onSeamEast = east.SampleZ(0f, y);
            Math.Abs(onSeamWest - onSeamEast).Should().BeLessThan(1e-4f, $"seed {seed}: seam at y {y}: west {onSeamWest:R}, east {onSeamEast:R}");

            // One float step either side of the seam, in the landblock-local frames.
            float below = MathF.BitDecrement(192f), above = MathF.BitIncrement(0f);
            double bound = 1e-4 + (gradient * (192f - below));
            Math.Abs(west.SampleZ(below, y) - onSeamEast).Should().BeLessThan((float)bound, $"seed {seed}: x {below:R} of west at y {y}");
            Math.Abs(east.SampleZ(above, y) - onSeamWest).Should().BeLessThan((float)bound, $"seed {seed}: x {above:R} of east at y {y}");
        }
    }

    [Theory]
    [InlineData(0x7F40FFFFu, 0x8040FFFFu, false)]
    [InlineData(0x7F40FFFFu, 0x8040FFFFu, true)]
    [InlineData(0xFD40FFFFu, 0xFE40FFFFu, false)] // the far east seam of the world, global frame: 4 mm float steps
    [InlineData(0xFD40FFFFu, 0xFE40FFFFu, true)]
    public void Resolve_StandingOnWorldSeamAndOneFloatStepEitherSide_OnGroundAndContinuous(uint west, uint east, bool centred)
    {
        (TerrainSurface westTerrain, TerrainSurface eastTerrain, double gradient) = SeamPair(4, west, east);
        var engine = centred ? new PhysicsEngine(east) : new PhysicsEngine();
        engine.AddLandblock(west, westTerrain, []);
        engine.AddLandblock(east, eastTerrain, []);
        float seam = engine.GetLandblockOrigin(east).X;
        float originY = engine.GetLandblockOrigin(east).Y;

        foreach (float x in new[] { MathF.BitDecrement(seam), seam, MathF.BitIncrement(seam) })
        {
            for (float y = 0.5f; y < 192f; y += 7.25f)
            {
                // Either cell id: the one the position is in, or the one across the seam (the caller's stale id).
                foreach (uint cell in new[] { (west & 0xFFFF0000u) | 0x0039u, (east & 0xFFFF0000u) | 0x0001u })
                {
                    var pos = new Vector3(x, originY + y, 0f);
                    ResolveResult r = engine.Resolve(pos, cell, Vector3.Zero, 1000f);
                    string what = $"x {x:R} (seam {seam:R}), y {y}, from 0x{cell:X8}, {(centred ? "centred" : "global")}";
                    r.IsOnGround.Should().BeTrue(what);

                    // The position is kept up to the float spacing of the landblock-local frame it is resolved
                    // in (near world 0 in the centred frame, ±1e-45 is finer than 192's 1.5e-5 m spacing and
                    // rounds onto the seam); the landblock is the one the kept position lies in.
                    r.Position.X.Should().BeApproximately(x, 1.6e-5f, what);
                    if (!centred)
                    {
                        r.Position.X.Should().Be(x, what);
                    }

                    (r.CellId & 0xFFFF0000u).Should().Be(r.Position.X >= seam ? east & 0xFFFF0000u : west & 0xFFFF0000u, $"{what}: a point on the seam belongs to the east landblock");

                    float reference = eastTerrain.SampleZ(0f, y);
                    double bound = 1e-4 + (gradient * Math.Abs(x - seam));
                    Math.Abs(r.Position.Z - reference).Should().BeLessThan((float)bound, what);
                }
            }
        }
    }

    [Theory]
    [InlineData(5)]
    [InlineData(6)]
    public void SampleZ_OnEveryCellEdgeVertexAndDiagonal_BothSidesAgreeWithin1e4(int seed)
    {
        var random = new Random(seed);
        byte[] heights = Gen.Heights(random);
        float[] table = NonLinearTable();
        var terrain = new TerrainSurface(heights, table, 0x1234FFFFu);
        double gradient = Reference.MaxGradient(heights, table);
        int probes = 0;
        for (int cx = 0; cx < 8; cx++)
        {
            for (int cy = 0; cy < 8; cy++)
            {
                for (int i = 0; i <= 64; i++)
                {
                    float t = i * 24f / 64f; // exact in float
                    float x0 = cx * 24f, y0 = cy * 24f;

                    // On the cell's west edge, its south edge, and both diagonals; each compared with one float step either side.
                    foreach ((float x, float y, float nx, float ny) in new[]
                    {
                        (x0, y0 + t, 1f, 0f),
                        (x0 + t, y0, 0f, 1f),
                        (x0 + t, y0 + t, 1f, -1f),
                        (x0 + t, y0 + 24f - t, 1f, 1f),
                    })
                    {
                        float z = terrain.SampleZ(x, y);
                        double exact = Reference.TerrainZ(heights, table, 0x12, 0x34, x, y);
                        Math.Abs(z - exact).Should().BeLessThan(1e-4f, $"seed {seed}: on the seam at ({x:R}, {y:R})");
                        float xa = nx > 0 ? MathF.BitIncrement(x) : nx < 0 ? MathF.BitDecrement(x) : x;
                        float ya = ny > 0 ? MathF.BitIncrement(y) : ny < 0 ? MathF.BitDecrement(y) : y;
                        float xb = nx > 0 ? MathF.BitDecrement(x) : nx < 0 ? MathF.BitIncrement(x) : x;
                        float yb = ny > 0 ? MathF.BitDecrement(y) : ny < 0 ? MathF.BitIncrement(y) : y;
                        double bound = 1e-4 + (gradient * 2 * (Math.Abs(xa - xb) + Math.Abs(ya - yb)));
                        Math.Abs(terrain.SampleZ(xa, ya) - terrain.SampleZ(xb, yb)).Should().BeLessThan((float)bound,
                            $"seed {seed}: either side of ({x:R}, {y:R}): ({xa:R}, {ya:R}) vs ({xb:R}, {yb:R})");
                        probes++;
                    }
                }
            }
        }

        probes.Should().Be(8 * 8 * 65 * 4);
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(37f)]
    [InlineData(90f)]
    [InlineData(180f)]
    public void SampleFloorZ_OnSharedEdgesAndVertices_AlwaysAFloorAndContinuous(float degrees)
    {
        // A 6 × 6 grid of 1 m squares on a tilted plane, each square its own polygon (two fan triangles),
        // placed far out in the landblock and rotated: every interior edge and vertex is shared.
        var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, degrees * MathF.PI / 180f);
        var origin = new Vector3(171.3f, 183.7f, 412.9f);
        var builder = new CellBuilder(0xFE000100u, origin, rotation);
        static float H(float x, float y) => (0.31f * x) - (0.17f * y);
        for (int i = 0; i < 6; i++)
        {
            for (int j = 0; j < 6; j++)
            {
                builder.Physics(new(i, j, H(i, j)), new(i + 1, j, H(i + 1, j)), new(i + 1, j + 1, H(i + 1, j + 1)), new(i, j + 1, H(i, j + 1)));
            }
        }

        CellSurface cell = builder.Build();
        int probes = 0;
        for (int i = 0; i <= 96; i++)
        {
            for (int line = 0; line <= 6; line++)
            {
                float s = i / 16f;
                foreach (Vector3 local in new[] { new Vector3(s, line, 0), new Vector3(line, s, 0), new Vector3(s, s, 0) })
                {
                    Vector3 p = origin + Vector3.Transform(local, rotation);
                    float expected = origin.Z + H(local.X, local.Y);
                    foreach ((float x, float y) in new[] { (p.X, p.Y), (MathF.BitIncrement(p.X), p.Y), (MathF.BitDecrement(p.X), p.Y), (p.X, MathF.BitIncrement(p.Y)), (p.X, MathF.BitDecrement(p.Y)) })
                    {
                        float? z = cell.SampleFloorZ(x, y);
                        string what = $"{degrees}°: cell-local {local} → ({x:R}, {y:R})";
                        z.Should().NotBeNull(what);
                        z!.Value.Should().BeApproximately(expected, 1e-4f, what);
                        probes++;
                    }
                }
            }
        }

        probes.Should().Be(97 * 7 * 3 * 5);
    }

    [Theory]
    [InlineData(0x00000000u, false)]
    [InlineData(0xFEFE0000u, false)]
    [InlineData(0xFEFE0000u, true)]
    public void Resolve_WalkingAlongLandblockSeamAndTerrainDiagonal_NeverLosesTheGround(uint landblock, bool centred)
    {
        // 2 × 2 landblocks (clamped to the world) of gentle hills sharing their seams; walk 4608 frames
        // north along the x seam, then 3000 frames south-west along cell diagonals (each cell's SW–NE
        // diagonal, or through the centre of its SE–NW one).
        int lx = Math.Min((int)(landblock >> 24), 0xFD), ly = Math.Min((int)((landblock >> 16) & 0xFF), 0xFD);
        uint Id(int dx, int dy) => ((uint)(lx + dx) << 24) | ((uint)(ly + dy) << 16) | 0xFFFFu;
        var engine = centred ? new PhysicsEngine(Id(1, 1)) : new PhysicsEngine();
        var table = NonLinearTable();
        for (int dx = 0; dx < 2; dx++)
        {
            for (int dy = 0; dy < 2; dy++)
            {
                int gx0 = dx * 8, gy0 = dy * 8;
                engine.AddLandblock(Id(dx, dy), new TerrainSurface(Heights((x, y) => 40 + ((gx0 + x) % 3) + ((gy0 + y) % 2)), table, Id(dx, dy)), []);
            }
        }

        // Steps of 1/16 m are exact in every frame, so the path stays exactly on the seam and then
        // exactly on the diagonal line through the cell corner (seam, 288) of the northern landblock.
        Vector3 origin = engine.GetLandblockOrigin(Id(1, 0));
        var pos = new Vector3(origin.X, origin.Y, 0f);
        uint cell = Id(1, 0) & 0xFFFF0000u;
        int frames = 0;
        foreach ((Vector3 step, int count) in new[] { (new Vector3(0, 0.0625f, 0), 4608), (new Vector3(-0.0625f, -0.0625f, 0), 3000) })
        {
            for (int i = 0; i < count; i++, frames++)
            {
                ResolveResult r = engine.Resolve(pos, cell, step, 1.5f);
                string what = $"frame {frames} from {pos:R} in 0x{cell:X8} by {step}, {(centred ? "centred" : "global")}";
                r.IsOnGround.Should().BeTrue(what);
                r.Position.Should().NotBe(pos, $"{what}: never rejected on gentle hills");
                if (step.X == 0)
                {
                    r.Position.X.Should().Be(origin.X, $"{what}: stays exactly on the seam");
                    (r.CellId & 0xFFFF0000u).Should().Be((Id(1, 0) & 0xFFFF0000u) + ((r.Position.Y >= origin.Y + 192f ? 1u : 0u) << 16), what);
                }
                else
                {
                    (r.Position.X - origin.X).Should().Be(r.Position.Y - origin.Y - 288f, $"{what}: stays exactly on the diagonal line");
                }

                (pos, cell) = (r.Position, r.CellId);
            }
        }

        frames.Should().Be(7608);
    }

    [Fact]
    public void Resolve_WalkingAlongFloorDiagonalAndOuterEdge_NeverLosesTheFloor()
    {
        // A sloped 8 × 8 m square floor (two fan triangles sharing the SW–NE diagonal), rotated 90°,
        // with an outdoor door; walk its diagonal and its outer edges for thousands of frames.
        var origin = new Vector3(60.25f, 70.5f, 30f);
        var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2);
        CellSurface room = new CellBuilder(0xA9B40100u, origin, rotation)
            .Physics(new(0, 0, 0), new(8, 0, 0.8f), new(8, 8, 1.2f), new(0, 8, 0.4f))
            .Build();
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(-50f), [room]);

        Vector3 World(float x, float y) => origin + Vector3.Transform(new Vector3(x, y, 0), rotation);
        float FloorAt(float x, float y) => origin.Z + (0.1f * x) + (0.05f * y);
        int frames = 0;
        foreach ((Vector2 from, Vector2 to) in new[] { (new Vector2(0, 0), new Vector2(8, 8)), (new Vector2(8, 8), new Vector2(8, 0)), (new Vector2(8, 0), new Vector2(0, 0)), (new Vector2(0, 0), new Vector2(0, 8)) })
        {
            Vector3 p0 = World(from.X, from.Y), p1 = World(to.X, to.Y);
            var pos = new Vector3(p0.X, p0.Y, FloorAt(from.X, from.Y));
            for (int i = 1; i <= 1000; i++, frames++)
            {
                Vector3 target = Vector3.Lerp(p0, p1, i / 1000f);
                ResolveResult r = engine.Resolve(pos, room.CellId, new Vector3(target.X - pos.X, target.Y - pos.Y, 0), 0.5f);
                Vector2 local = from + ((to - from) * (i / 1000f));
                string what = $"frame {frames}: {from} → {to}, step {i} at {pos:R}";
                r.IsOnGround.Should().BeTrue(what);
                r.CellId.Should().Be(room.CellId, what);
                r.Position.Z.Should().BeApproximately(FloorAt(local.X, local.Y), 1e-4f, what);
                pos = r.Position;
            }
        }

        frames.Should().Be(4000);
    }
}
