using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The terrain's normal, corners and diagonals against references written here in double from the
/// vertex positions, on random heights, both surfaces, every cell and both diagonals.
/// </summary>
[Trait("Mutation", "TerrainSurface")]
public class TerrainNormalTests
{
    private const double Cell = 24.0;

    /// <summary>Landblocks whose 64 cells together hold both diagonals in many bit positions.</summary>
    private static readonly uint[] Landblocks = [Holtburg, 0x1234FFFFu, 0x0000FFFFu, 0xFEFEFFFFu, 0x7F01FFFFu];

    private static double H(byte[] heights, float[] table, int vx, int vy) => table[heights[(vx * 9) + vy]];

    /// <summary>The upward unit normal of the plane through three points, in double.</summary>
    private static (double X, double Y, double Z) PlaneNormal((double X, double Y, double Z) a, (double X, double Y, double Z) b, (double X, double Y, double Z) c)
    {
        double ux = b.X - a.X, uy = b.Y - a.Y, uz = b.Z - a.Z;
        double vx = c.X - a.X, vy = c.Y - a.Y, vz = c.Z - a.Z;
        double nx = (uy * vz) - (uz * vy), ny = (uz * vx) - (ux * vz), nz = (ux * vy) - (uy * vx);
        double length = Math.Sqrt((nx * nx) + (ny * ny) + (nz * nz)) * Math.Sign(nz);
        return (nx / length, ny / length, nz / length);
    }

    /// <summary>
    /// The game triangle's normal at fractions (u, v) of cell (cx, cy): the triangle's three corners
    /// in metres. On the diagonal (u = v for SW–NE, u + v = 1 for SE–NW) it is the triangle that
    /// holds the cell's south edge, as a point on a cell edge belongs to the cell north of it.
    /// </summary>
    private static (double X, double Y, double Z) TriangleNormal(byte[] heights, float[] table, int cx, int cy, bool swToNe, double u, double v)
    {
        var sw = (0.0, 0.0, H(heights, table, cx, cy));
        var se = (Cell, 0.0, H(heights, table, cx + 1, cy));
        var nw = (0.0, Cell, H(heights, table, cx, cy + 1));
        var ne = (Cell, Cell, H(heights, table, cx + 1, cy + 1));
        if (swToNe)
        {
            return u >= v ? PlaneNormal(sw, se, ne) : PlaneNormal(sw, ne, nw);
        }

        return u + v <= 1 ? PlaneNormal(sw, se, nw) : PlaneNormal(ne, nw, se);
    }

    /// <summary>The bilinear patch's tangent-plane normal: the gradient of Σ h·weight, differentiated weight by weight.</summary>
    private static (double X, double Y, double Z) BilinearNormal(byte[] heights, float[] table, int cx, int cy, double u, double v)
    {
        double sw = H(heights, table, cx, cy), se = H(heights, table, cx + 1, cy);
        double nw = H(heights, table, cx, cy + 1), ne = H(heights, table, cx + 1, cy + 1);

        // z = sw(1−u)(1−v) + se·u(1−v) + nw(1−u)v + ne·uv, in metres per cell.
        double dzdu = (-sw * (1 - v)) + (se * (1 - v)) - (nw * v) + (ne * v);
        double dzdv = (-sw * (1 - u)) - (se * u) + (nw * (1 - u)) + (ne * u);
        double gx = dzdu / Cell, gy = dzdv / Cell;
        double length = Math.Sqrt(1 + (gx * gx) + (gy * gy));
        return (-gx / length, -gy / length, 1 / length);
    }

    private static void ShouldBe(Vector3 actual, (double X, double Y, double Z) expected, string because)
    {
        actual.X.Should().BeApproximately((float)expected.X, 2e-6f, because);
        actual.Y.Should().BeApproximately((float)expected.Y, 2e-6f, because);
        actual.Z.Should().BeApproximately((float)expected.Z, 2e-6f, because);
    }

    [Fact]
    public void Normal_of_the_game_triangles_is_the_plane_of_the_triangle_under_the_point()
    {
        var random = new Random(29);
        float[] table = NonLinearTable();
        int[] seen = new int[4]; // SW–NE below, SW–NE above, SE–NW below, SE–NW above
        foreach (uint landblock in Landblocks)
        {
            byte[] heights = RandomHeights(random);
            var terrain = new TerrainSurface(heights, table, landblock);
            uint gx0 = (landblock >> 24) * 8, gy0 = ((landblock >> 16) & 0xFF) * 8;
            for (int cx = 0; cx < 8; cx++)
            {
                for (int cy = 0; cy < 8; cy++)
                {
                    bool swToNe = TerrainSurface.IsSplitSwToNe(gx0 + (uint)cx, gy0 + (uint)cy);
                    foreach ((double fu, double fv) in new[] { (0.8, 0.1), (0.1, 0.8), (0.3, 0.4), (0.7, 0.6), (random.NextDouble(), random.NextDouble()) })
                    {
                        float x = (float)((cx + fu) * Cell), y = (float)((cy + fv) * Cell);
                        double u = (x / Cell) - cx, v = (y / Cell) - cy;
                        var expected = TriangleNormal(heights, table, cx, cy, swToNe, u, v);
                        Vector3 normal = terrain.NormalUnchecked(x, y);
                        ShouldBe(normal, expected, $"landblock 0x{landblock:X8}, cell ({cx}, {cy}), split SW–NE {swToNe}, at ({x}, {y})");
                        terrain.NormalZUnchecked(x, y).Should().Be(normal.Z);
                        seen[(swToNe ? 0 : 2) + ((swToNe ? u >= v : u + v <= 1) ? 0 : 1)]++;
                    }
                }
            }
        }

        seen.Should().OnlyContain(count => count > 50, "every triangle of both diagonals is probed");
    }

    [Fact]
    public void Normal_on_the_diagonal_is_that_of_the_triangle_holding_the_south_edge()
    {
        // At a cell's centre u = v = 0.5 exactly: on the SW–NE diagonal and on the SE–NW one. The two
        // triangles there have different planes; the normal is the south one's, as SampleZ's formula.
        var random = new Random(31);
        float[] table = LinearTable();
        int[] seen = new int[2];
        foreach (uint landblock in Landblocks)
        {
            byte[] heights = RandomHeights(random);
            var terrain = new TerrainSurface(heights, table, landblock);
            for (int cx = 0; cx < 8; cx++)
            {
                for (int cy = 0; cy < 8; cy++)
                {
                    bool swToNe = terrain.IsSplitSwToNe(cx, cy);
                    float x = (float)((cx + 0.5) * Cell), y = (float)((cy + 0.5) * Cell);
                    ((x / Cell) - cx).Should().Be(0.5, "the probe is on the diagonal");
                    var expected = TriangleNormal(heights, table, cx, cy, swToNe, 0.5, 0.5);
                    ShouldBe(terrain.NormalUnchecked(x, y), expected, $"centre of cell ({cx}, {cy}) of 0x{landblock:X8}, split SW–NE {swToNe}");
                    seen[swToNe ? 0 : 1]++;
                }
            }
        }

        seen.Should().OnlyContain(count => count > 50, "both diagonals are probed");
    }

    [Fact]
    public void Normal_of_the_bilinear_patch_is_its_tangent_plane()
    {
        var random = new Random(37);
        float[] table = NonLinearTable();
        for (int n = 0; n < 4; n++)
        {
            byte[] heights = RandomHeights(random);
            var terrain = new TerrainSurface(heights, table);
            for (int cx = 0; cx < 8; cx++)
            {
                for (int cy = 0; cy < 8; cy++)
                {
                    float x = (float)((cx + random.NextDouble()) * Cell), y = (float)((cy + random.NextDouble()) * Cell);
                    double u = (x / Cell) - cx, v = (y / Cell) - cy;
                    if (u >= 1 || v >= 1)
                    {
                        continue; // rounded onto the next cell's edge
                    }

                    Vector3 normal = terrain.NormalUnchecked(x, y);
                    ShouldBe(normal, BilinearNormal(heights, table, cx, cy, u, v), $"bilinear case {n}, cell ({cx}, {cy}), at ({x}, {y})");
                    terrain.NormalZUnchecked(x, y).Should().Be(normal.Z);
                }
            }
        }
    }

    [Fact]
    public void Normal_of_a_plane_tilted_both_ways_has_the_plane_slope_and_sign()
    {
        // Z = 2·vx − 3·vy metres (a plane): every triangle and the bilinear patch have the same normal,
        // (−2/24, 3/24, 1) normalised: downhill is −x and +y.
        byte[] heights = Heights((vx, vy) => 30 + vx - (2 * vy));
        float[] table = LinearTable(); // 2 m per index
        double gx = 2.0 / 24, gy = -4.0 / 24, n = 1 / Math.Sqrt(1 + (gx * gx) + (gy * gy));
        foreach (TerrainSurface terrain in new[] { new TerrainSurface(heights, table), new TerrainSurface(heights, table, Holtburg), new TerrainSurface(heights, table, 0x1234FFFFu) })
        {
            foreach ((float x, float y) in new[] { (1f, 1f), (20f, 3f), (3f, 20f), (100f, 150f), (191f, 191f), (12f, 12f) })
            {
                ShouldBe(terrain.NormalUnchecked(x, y), (-gx * n, -gy * n, n), $"plane at ({x}, {y}), triangles {terrain.LandblockId is not null}");
            }
        }

        var flat = new TerrainSurface(FlatHeights(7), table, Holtburg);
        flat.NormalUnchecked(50f, 60f).Should().Be(Vector3.UnitZ);
    }

    [Fact]
    public void Corners_are_the_heights_of_the_cell_vertices()
    {
        var random = new Random(41);
        byte[] heights = RandomHeights(random);
        float[] table = NonLinearTable();
        var terrain = new TerrainSurface(heights, table, Holtburg);
        for (int cx = 0; cx < 8; cx++)
        {
            for (int cy = 0; cy < 8; cy++)
            {
                terrain.Corners(cx, cy, out double sw, out double nw, out double se, out double ne);
                string because = $"cell ({cx}, {cy})";
                sw.Should().Be(H(heights, table, cx, cy), because);
                nw.Should().Be(H(heights, table, cx, cy + 1), because);
                se.Should().Be(H(heights, table, cx + 1, cy), because);
                ne.Should().Be(H(heights, table, cx + 1, cy + 1), because);
            }
        }
    }

    [Fact]
    public void Each_cell_of_a_landblock_has_the_game_diagonal_of_its_global_cell()
    {
        int swToNeCount = 0;
        foreach (uint landblock in Landblocks)
        {
            var terrain = new TerrainSurface(FlatHeights(0), LinearTable(), landblock);
            uint gx0 = (landblock >> 24) * 8, gy0 = ((landblock >> 16) & 0xFF) * 8;
            for (int cx = 0; cx < 8; cx++)
            {
                for (int cy = 0; cy < 8; cy++)
                {
                    bool expected = TerrainSurface.IsSplitSwToNe(gx0 + (uint)cx, gy0 + (uint)cy);
                    terrain.IsSplitSwToNe(cx, cy).Should().Be(expected, $"cell ({cx}, {cy}) of 0x{landblock:X8}");
                    swToNeCount += expected ? 1 : 0;
                }
            }
        }

        swToNeCount.Should().BeInRange(40, (64 * Landblocks.Length) - 40, "both diagonals occur");
    }

    [Fact]
    public void SampleZ_of_the_game_triangles_is_the_plane_of_the_triangle_under_the_point()
    {
        var random = new Random(43);
        float[] table = NonLinearTable();
        foreach (uint landblock in Landblocks)
        {
            byte[] heights = RandomHeights(random);
            var terrain = new TerrainSurface(heights, table, landblock);
            for (int cx = 0; cx < 8; cx++)
            {
                for (int cy = 0; cy < 8; cy++)
                {
                    bool swToNe = terrain.IsSplitSwToNe(cx, cy);
                    foreach ((double fu, double fv) in new[] { (0.8, 0.1), (0.1, 0.8), (0.3, 0.4), (0.7, 0.6), (0.5, 0.5) })
                    {
                        float x = (float)((cx + fu) * Cell), y = (float)((cy + fv) * Cell);
                        double u = (x / Cell) - cx, v = (y / Cell) - cy;
                        var (nx, ny, nz) = TriangleNormal(heights, table, cx, cy, swToNe, u, v);

                        // The plane through the SW or NE corner (both are on both triangles of a SW–NE cell;
                        // SE is on both triangles of a SE–NW cell).
                        (double px, double py, double pz) = swToNe ? (0.0, 0.0, H(heights, table, cx, cy)) : (Cell, 0.0, H(heights, table, cx + 1, cy));
                        double z = pz - (((nx * ((u * Cell) - px)) + (ny * ((v * Cell) - py))) / nz);
                        terrain.SampleZ(x, y).Should().BeApproximately((float)z, 1e-3f, $"cell ({cx}, {cy}) of 0x{landblock:X8}, split SW–NE {swToNe}, at ({x}, {y})");
                    }
                }
            }
        }
    }

    [Theory]
    [InlineData(float.NaN, 1f, "localX")]
    [InlineData(1f, float.PositiveInfinity, "localY")]
    [InlineData(float.NegativeInfinity, float.NaN, "localX")]
    public void A_position_that_is_not_finite_is_refused_with_the_position_in_the_message(float x, float y, string name)
    {
        var terrain = new TerrainSurface(FlatHeights(0), LinearTable(), Holtburg);
        string message = $"terrain position ({x}, {y}) must be finite.*";
        FluentActions.Invoking(() => terrain.SampleZ(x, y)).Should().Throw<ArgumentException>().WithParameterName(name).WithMessage(message);
        FluentActions.Invoking(() => terrain.ComputeOutdoorCellId(x, y)).Should().Throw<ArgumentException>().WithParameterName(name).WithMessage(message);
    }

    [Fact]
    public void Bad_arrays_of_the_bilinear_surface_are_refused_naming_the_terrain()
    {
        FluentActions.Invoking(() => new TerrainSurface(new byte[80], LinearTable())).Should().Throw<ArgumentException>()
            .WithParameterName("heights").WithMessage("terrain: heights must have 81 entries (9 × 9 vertices), not 80.*");
        FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), new float[3])).Should().Throw<ArgumentException>()
            .WithParameterName("heightTable").WithMessage("terrain: heightTable must have 256 entries, not 3.*");
        FluentActions.Invoking(() => new TerrainSurface(new byte[80], LinearTable(), 0x1234FFFFu)).Should().Throw<ArgumentException>()
            .WithParameterName("heights").WithMessage("landblock 0x1234FFFF: heights must have 81 entries*");
        FluentActions.Invoking(() => new TerrainSurface(null!, LinearTable())).Should().Throw<ArgumentNullException>().WithParameterName("heights");
        FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), null!, Holtburg)).Should().Throw<ArgumentNullException>().WithParameterName("heightTable");
        foreach (int index in new[] { 0, 200, 255 })
        {
            float[] table = LinearTable();
            table[index] = float.NegativeInfinity;
            FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), table)).Should().Throw<ArgumentException>()
                .WithParameterName("heightTable").WithMessage($"terrain: heightTable[{index}] is {float.NegativeInfinity}; heights must be finite.*");
        }
    }

    [Theory]
    [InlineData(0xA9B4FFFFu, 0xA9B4FFFFu)]
    [InlineData(0x12340000u, 0x1234FFFFu)]
    [InlineData(0x0000FFFFu, 0x0000FFFFu)]
    public void The_game_surface_names_its_landblock_and_refuses_an_id_that_is_not_one(uint given, uint named)
    {
        new TerrainSurface(FlatHeights(0), LinearTable(), given).LandblockId.Should().Be(named);
        new TerrainSurface(FlatHeights(0), LinearTable()).LandblockId.Should().BeNull();
        FluentActions.Invoking(() => new TerrainSurface(FlatHeights(0), LinearTable(), given ^ 1u)).Should().Throw<ArgumentException>()
            .WithParameterName("landblockId").WithMessage($"*0x{given ^ 1u:X8}*");
    }

    [Fact]
    public void The_unchecked_sample_is_the_checked_one()
    {
        var random = new Random(47);
        byte[] heights = RandomHeights(random);
        foreach (TerrainSurface terrain in new[] { new TerrainSurface(heights, NonLinearTable()), new TerrainSurface(heights, NonLinearTable(), Holtburg) })
        {
            for (int k = 0; k < 200; k++)
            {
                float x = (float)((random.NextDouble() * 200) - 4), y = (float)((random.NextDouble() * 200) - 4);
                terrain.SampleZUnchecked(x, y).Should().Be(terrain.SampleZ(x, y), $"at ({x}, {y})");
            }
        }
    }
}
