using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

[Trait("Mutation", "TerrainSurface")]
public class TerrainSurfaceTests
{
    /// <summary>Independent bilinear reference in double: the formula of GameWindow.SampleTerrainZ.</summary>
    private static double BilinearReference(byte[] heights, float[] table, double x, double y)
    {
        x = Math.Clamp(x, 0, 192);
        y = Math.Clamp(y, 0, 192);
        int cx = Math.Min((int)(x / 24), 7), cy = Math.Min((int)(y / 24), 7);
        double u = (x / 24) - cx, v = (y / 24) - cy;
        double h(int i, int j) => table[heights[(i * 9) + j]];
        return (h(cx, cy) * (1 - u) * (1 - v)) + (h(cx + 1, cy) * u * (1 - v)) + (h(cx, cy + 1) * (1 - u) * v) + (h(cx + 1, cy + 1) * u * v);
    }

    [Theory]
    [InlineData(0f, 0f)]
    [InlineData(96f, 96f)]
    [InlineData(191.9f, 0.1f)]
    [InlineData(192f, 192f)]
    [InlineData(37.5f, 150.25f)]
    public void SampleZ_FlatTerrain_ReturnsThatValueEverywhere(float x, float y)
    {
        var bilinear = new TerrainSurface(FlatHeights(25), LinearTable());
        var retail = new TerrainSurface(FlatHeights(25), LinearTable(), Holtburg);

        bilinear.SampleZ(x, y).Should().Be(50f, $"flat bilinear terrain at ({x}, {y})");
        retail.SampleZ(x, y).Should().Be(50f, $"flat retail terrain at ({x}, {y})");
    }

    [Theory]
    [InlineData(12f, 5f, 1f)] // half-way between vertex 0 (0 m) and 1 (2 m)
    [InlineData(36f, 100f, 3f)]
    [InlineData(90f, 7f, 7.5f)]
    [InlineData(192f, 50f, 16f)]
    public void SampleZ_SlopeAlongX_ReturnsInterpolatedValues(float x, float y, float expected)
    {
        byte[] heights = Heights((vx, _) => vx); // Z = 2·vx m: 1 m every 12 m
        foreach (TerrainSurface terrain in new[] { new TerrainSurface(heights, LinearTable()), new TerrainSurface(heights, LinearTable(), Holtburg) })
        {
            terrain.SampleZ(x, y).Should().BeApproximately(expected, 1e-4f, $"slope Z at ({x}, {y}), retail = {terrain.LandblockId is not null}");
        }
    }

    [Fact]
    public void SampleZ_Bilinear_MatchesReferenceFormulaOnRandomTerrain()
    {
        var random = new Random(5);
        for (int n = 0; n < 200; n++)
        {
            byte[] heights = RandomHeights(random);
            float[] table = NonLinearTable();
            var terrain = new TerrainSurface(heights, table);
            for (int k = 0; k < 20; k++)
            {
                float x = (float)(random.NextDouble() * 200) - 4, y = (float)(random.NextDouble() * 200) - 4;
                double expected = BilinearReference(heights, table, x, y);
                terrain.SampleZ(x, y).Should().BeApproximately((float)expected, 2e-3f, $"case {n}/{k} at ({x}, {y})");
            }
        }
    }

    [Theory]
    [InlineData(-10f, 50f, 0f, 50f)]
    [InlineData(250f, 50f, 192f, 50f)]
    [InlineData(50f, -0.5f, 50f, 0f)]
    [InlineData(50f, 1000f, 50f, 192f)]
    [InlineData(-5f, -5f, 0f, 0f)]
    [InlineData(300f, 300f, 192f, 192f)]
    public void SampleZ_OutsideLandblock_ClampsToBoundary(float x, float y, float clampedX, float clampedY)
    {
        byte[] heights = Heights((vx, vy) => (vx * 3) + (vy * 7));
        var bilinear = new TerrainSurface(heights, NonLinearTable());
        var retail = new TerrainSurface(heights, NonLinearTable(), Holtburg);

        bilinear.SampleZ(x, y).Should().Be(bilinear.SampleZ(clampedX, clampedY));
        retail.SampleZ(x, y).Should().Be(retail.SampleZ(clampedX, clampedY));
    }

    [Theory]
    [InlineData(0f, 0f, 0x0001u)]
    [InlineData(23f, 0f, 0x0001u)]
    [InlineData(24f, 0f, 0x0009u)]
    [InlineData(0f, 24f, 0x0002u)]
    [InlineData(191f, 191f, 0x0040u)]
    [InlineData(192f, 192f, 0x0040u)]
    [InlineData(23.999f, 47.999f, 0x0002u)]
    [InlineData(-3f, 500f, 0x0008u)]
    public void ComputeOutdoorCellId_GridIsXMajorFromOne(float x, float y, uint expected)
    {
        new TerrainSurface(FlatHeights(0), LinearTable()).ComputeOutdoorCellId(x, y).Should().Be(expected, $"cell of ({x}, {y})");
    }

    [Theory]
    [InlineData(0u, 0u, 0xAE6470DBu, true)]
    [InlineData(1u, 0u, 0x6C488D1Eu, false)]
    [InlineData(0u, 1u, 0x1A7F3662u, false)]
    [InlineData(1u, 1u, 0xE52E12D8u, true)]
    [InlineData(2u, 3u, 0xBB3D7B28u, true)]
    [InlineData(1355u, 1445u, 0x7EBDEBD4u, false)]
    [InlineData(1359u, 1440u, 0xA1E87708u, true)]
    [InlineData(2039u, 2039u, 0x3846F0E4u, false)]
    public void SplitValue_MatchesGameOracle(uint gx, uint gy, uint raw, bool swToNe)
    {
        TerrainSurface.SplitValue(gx, gy).Should().Be(raw, $"split of global cell ({gx}, {gy})");
        TerrainSurface.IsSplitSwToNe(gx, gy).Should().Be(swToNe);
    }

    [Fact]
    public void SampleZ_Retail_FollowsHoltburgDiagonalMap()
    {
        // Rows from cy = 7 (north) down to 0; '/' = SW–NE, '\' = SE–NW.
        string[] map =
        [
            "////////",
            "////////",
            @"///\\\\\",
            @"//\\\\\/",
            @"//\\\///",
            @"//\\//\\",
            @"/\\//\\/",
            @"/\\//\//",
        ];

        // Only the NE corner of the cell is raised, so the diagonal decides the Z of a point near SW.
        for (int cx = 0; cx < 8; cx++)
        {
            for (int cy = 0; cy < 8; cy++)
            {
                byte[] heights = Heights((x, y) => x == cx + 1 && y == cy + 1 ? 100 : 0);
                var terrain = new TerrainSurface(heights, LinearTable(), Holtburg);

                // Probe at (0.25, 0.25) of the cell: SW–NE puts it on the diagonal's side touching NE
                // (Z = 200·0.25 = 50 m); SE–NW puts it in (SW, SE, NW), all low (Z = 0).
                float z = terrain.SampleZ((cx + 0.25f) * 24f, (cy + 0.25f) * 24f);
                char expected = map[7 - cy][cx];
                char actual = z > 1f ? '/' : '\\';
                actual.Should().Be(expected, $"diagonal of cell ({cx}, {cy}) of 0xA9B4, probe Z {z}");
            }
        }
    }

    [Fact]
    public void SampleZ_Retail_DiffersFromBilinearAtCellCentreByQuarterOfTwist()
    {
        // Cell (0,0) of 0xA9B4 (global 1352, 1440): SW, SE, NW at 0 m, NE at 40 m.
        byte[] heights = Heights((x, y) => x == 1 && y == 1 ? 20 : 0);
        var bilinear = new TerrainSurface(heights, LinearTable());
        var retail = new TerrainSurface(heights, LinearTable(), Holtburg);

        float twist = 40f / 4f; // |h_SW + h_NE − h_SE − h_NW| / 4
        bilinear.SampleZ(12f, 12f).Should().BeApproximately(10f, 1e-4f);
        MathF.Abs(retail.SampleZ(12f, 12f) - bilinear.SampleZ(12f, 12f)).Should().BeApproximately(twist, 1e-3f,
            "at the centre the diagonal is either on the raised corner's plane (20 m) or flat (0 m)");
    }

    [Fact]
    public void SampleZ_Retail_IsContinuousAcrossEveryCellEdgeAndDiagonal()
    {
        var random = new Random(7);
        byte[] heights = RandomHeights(random);
        float[] table = NonLinearTable();
        var terrain = new TerrainSurface(heights, table, 0x1234FFFFu);

        // Probes 1e-5 m to each side of a seam differ by at most the steepest gradient × 2e-5 m,
        // plus float rounding; a wrong diagonal or a jump would differ by metres.
        const float eps = 1e-5f;
        float gradient = 2f * (heights.Max(b => table[b]) - heights.Min(b => table[b])) / 24f;
        float bound = (2f * eps * gradient) + 2e-4f;
        for (int i = 1; i < 8; i++)
        {
            for (float s = 0f; s <= 192f; s += 1.5f)
            {
                float e = i * 24f;
                Math.Abs(terrain.SampleZ(e - eps, s) - terrain.SampleZ(e + eps, s)).Should().BeLessThan(bound, $"x edge {e} at y {s}");
                Math.Abs(terrain.SampleZ(s, e - eps) - terrain.SampleZ(s, e + eps)).Should().BeLessThan(bound, $"y edge {e} at x {s}");
            }
        }

        for (int cx = 0; cx < 8; cx++)
        {
            for (int cy = 0; cy < 8; cy++)
            {
                for (float f = 0.1f; f < 1f; f += 0.2f)
                {
                    // Both diagonals of the cell, probed a hair to each side.
                    float x0 = (cx + f) * 24f, y0 = (cy + f) * 24f, y1 = (cy + 1 - f) * 24f;
                    Math.Abs(terrain.SampleZ(x0 + eps, y0) - terrain.SampleZ(x0, y0 + eps)).Should().BeLessThan(bound, $"SW–NE diagonal of ({cx}, {cy})");
                    Math.Abs(terrain.SampleZ(x0 + eps, y1) - terrain.SampleZ(x0 - eps, y1)).Should().BeLessThan(bound, $"SE–NW diagonal of ({cx}, {cy})");
                }
            }
        }
    }

    [Fact]
    public void SampleZ_Retail_IsContinuousAcrossLandblockSeam()
    {
        // Two landblocks sharing the seam column: west's x = 8 column equals east's x = 0 column.
        var random = new Random(11);
        byte[] west = RandomHeights(random), east = RandomHeights(random);
        for (int y = 0; y < 9; y++)
        {
            east[y] = west[(8 * 9) + y];
        }

        var westSurface = new TerrainSurface(west, NonLinearTable(), 0xA9B4FFFFu);
        var eastSurface = new TerrainSurface(east, NonLinearTable(), 0xAAB4FFFFu);
        for (float y = 0f; y <= 192f; y += 0.75f)
        {
            westSurface.SampleZ(192f, y).Should().BeApproximately(eastSurface.SampleZ(0f, y), 1e-4f, $"seam at y {y}");
        }
    }

    [Fact]
    public void SampleZ_UsesHeightTableNotTwiceTheByte()
    {
        var terrain = new TerrainSurface(FlatHeights(10), NonLinearTable(), Holtburg);
        terrain.SampleZ(50f, 50f).Should().Be(NonLinearTable()[10]).And.NotBe(20f);
    }
}
