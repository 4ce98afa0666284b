using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// The floor grid's size and answers: a cell of thousands of stacked whole-cell floors (every
/// triangle overlapping every grid square) stays small, and the grid answers bit for bit as the
/// brute-force loop over all triangles does, on random stacked cells.
/// </summary>
public class FloorGridTests
{
    /// <summary>
    /// 8,000 floors of 10 m × 10 m, one every 0.25 m from Z = 5 up (16,000 triangles, each covering
    /// the whole cell): the grid used to list every triangle in each of its 64 × 64 squares (65 million entries, 250 MiB).
    /// </summary>
    [Fact]
    public void CellSurface_8000StackedWholeCellFloors_BuildsUnder16MiBAndAnswersTheNearestFloor()
    {
        CellBuilder builder = StackedCell(8000);
        long before = GC.GetAllocatedBytesForCurrentThread();
        CellSurface cell = builder.Build();
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;

        allocated.Should().BeLessThan(16L << 20, $"building the stacked cell allocated {allocated:N0} bytes ({allocated / 1048576.0:F1} MiB)");

        // (25.3, 32.1) is off the squares' fan diagonal: exactly one triangle per floor contains it.
        cell.SampleFloorZ(25.3f, 32.1f).Should().Be(5f + (7999 * 0.25f), "no reference: the topmost floor");
        cell.SampleFloorZ(25.3f, 32.1f, 1005.1f).Should().Be(1005f, "the floor nearest Z 1005.1");
        cell.SampleFloorZ(25.3f, 32.1f, 1005.125f).Should().Be(1005.25f, "an exact tie between 1005 and 1005.25: the higher");
        cell.SampleFloorZ(25.3f, 32.1f, -1000f).Should().Be(5f, "below the stack: the lowest floor");
        cell.SampleFloorZ(25.3f, 32.1f, 1e6f).Should().Be(5f + (7999 * 0.25f), "far above the stack: the topmost floor");
        cell.SampleFloorZ(31f, 32.1f, 1005.1f).Should().BeNull("outside the floors");
    }

    /// <summary>
    /// Random cells of 17–3,000 floor triangles: stacks of whole-area floors on a few Z levels (exact
    /// duplicates and ties), overlapping rectangles and ramps, small tiles, thin fans; queries on
    /// vertices, edge midpoints and random points, with reference Z on a level, halfway between two,
    /// random, ±1e30 (every distance rounds to the same) and +∞. The grid's answer must be the
    /// brute-force selection over all triangles bit for bit, and its size within the entry budget.
    /// </summary>
    [Theory]
    [InlineData(808)]
    [InlineData(909)]
    public void FloorGrid_RandomStackedCells_BitIdenticalToBruteForceAndWithinBudget(int seed)
    {
        var random = new Random(seed);
        int compared = 0, found = 0, sortedSquares = 0;
        for (int n = 0; n < 60; n++)
        {
            (FloorTriangle[] triangles, float[] levels, string kind) = RandomStack(random);
            Vector2 min = triangles[0].Min, max = triangles[0].Max;
            foreach (FloorTriangle t in triangles)
            {
                min = Vector2.Min(min, t.Min);
                max = Vector2.Max(max, t.Max);
            }

            var grid = new FloorGrid(triangles, min, max);
            string cell = $"seed {seed}, cell {n} ({kind}, {triangles.Length} triangles, {levels.Length} levels, grid of {grid.SquareCount} squares, {grid.EntryCount} entries)";
            grid.EntryCount.Should().BeLessThanOrEqualTo(PhysicsConstants.MaxFloorGridEntriesPerTriangle * triangles.Length, cell);
            sortedSquares += grid.EntryCount / grid.SquareCount > PhysicsConstants.FloorGridLinearScanMax ? 1 : 0;

            for (int k = 0; k < 300; k++)
            {
                FloorTriangle t = triangles[random.Next(triangles.Length)];
                (float x, float y) = (k % 4) switch
                {
                    0 => random.Next(3) switch { 0 => (t.A.X, t.A.Y), 1 => (t.B.X, t.B.Y), _ => (t.C.X, t.C.Y) },
                    1 => ((t.A.X + t.B.X) / 2, (t.A.Y + t.B.Y) / 2),
                    _ => (Gen.Range(random, min.X - 0.5, max.X + 0.5), Gen.Range(random, min.Y - 0.5, max.Y + 0.5)),
                };
                int level = random.Next(levels.Length);
                float referenceZ = random.Next(7) switch
                {
                    0 => levels[level],
                    1 => level + 1 < levels.Length ? (levels[level] + levels[level + 1]) / 2 : levels[level] + 0.5f,
                    2 => float.PositiveInfinity,
                    3 => random.Next(2) == 0 ? 1e30f : -1e30f,
                    _ => Gen.Range(random, levels[0] - 3, levels[^1] + 3),
                };

                (bool expectedFound, float expected) = BruteForce(triangles, x, y, referenceZ);
                bool actualFound = grid.TrySample(x, y, referenceZ, out float actual);
                string what = $"{cell}, query {k} at ({x:R}, {y:R}), reference Z {referenceZ:R}: grid {(actualFound ? actual.ToString("R") : "none")}, brute force {(expectedFound ? expected.ToString("R") : "none")}";
                actualFound.Should().Be(expectedFound, what);
                if (expectedFound)
                {
                    BitConverter.SingleToInt32Bits(actual).Should().Be(BitConverter.SingleToInt32Bits(expected), what);
                    found++;
                }

                compared++;
            }
        }

        compared.Should().Be(18_000);
        found.Should().BeGreaterThan(9_000, "most queries are over a floor");
        sortedSquares.Should().BeGreaterThan(20, "most cells have squares long enough to be searched by Z");
    }

    /// <summary>The documented selection over every triangle: nearest |Z − reference| in float, on an exact tie the higher.</summary>
    private static (bool Found, float Z) BruteForce(FloorTriangle[] triangles, float x, float y, float referenceZ)
    {
        var zs = new List<float>();
        foreach (FloorTriangle t in triangles)
        {
            if (t.TrySample(x, y, out float z))
            {
                zs.Add(z);
            }
        }

        if (zs.Count == 0)
        {
            return (false, 0f);
        }

        float nearest = zs.Min(z => MathF.Abs(z - referenceZ));
        return (true, zs.Where(z => MathF.Abs(z - referenceZ) == nearest).Max());
    }

    /// <summary>Landblock-local floor triangles of one random stacked cell, its Z levels (ascending) and what kind it is.</summary>
    private static (FloorTriangle[] Triangles, float[] Levels, string Kind) RandomStack(Random random)
    {
        var origin = new Vector2(Gen.Range(random, -20, 200), Gen.Range(random, -20, 200));
        float step = random.Next(3) switch { 0 => 0.25f, 1 => 0.001f, _ => Gen.Range(random, 0.01, 3) };
        float baseZ = Gen.Range(random, -60, 160);
        var levels = new float[random.Next(1, 60)];
        for (int i = 0; i < levels.Length; i++)
        {
            levels[i] = baseZ + (i * step);
        }

        float Level() => levels[random.Next(levels.Length)];
        var triangles = new List<FloorTriangle>();
        int kind = random.Next(4);
        int target = random.Next(17, random.Next(2) == 0 ? 300 : 3000);
        while (triangles.Count < target)
        {
            switch (kind)
            {
                case 0: // whole-area floors, stacked: every triangle over the whole cell
                    AddQuad(triangles, origin, origin + new Vector2(10f, 8f), Level(), slope: Vector2.Zero);
                    break;
                case 1: // overlapping rectangles of all sizes, some of them ramps
                    Vector2 a = origin + new Vector2(Gen.Range(random, 0, 20), Gen.Range(random, 0, 20));
                    Vector2 size = new(Gen.Range(random, 0.05, 20), Gen.Range(random, 0.05, 20));
                    Vector2 slope = random.Next(3) == 0 ? new Vector2(Gen.Range(random, -0.8, 0.8), Gen.Range(random, -0.8, 0.8)) : Vector2.Zero;
                    AddQuad(triangles, a, a + size, Level(), slope);
                    break;
                case 2: // 1 m tiles over 12 m × 12 m, each on a level: a real cell's layout, stacked
                    var tile = origin + new Vector2(random.Next(12), random.Next(12));
                    AddQuad(triangles, tile, tile + Vector2.One, Level(), slope: Vector2.Zero);
                    break;
                default: // a flat 64-gon (a fan of long thin triangles) on a level
                    float z = Level();
                    var v = new Vector3[64];
                    for (int i = 0; i < v.Length; i++)
                    {
                        float angle = i * MathF.Tau / v.Length;
                        v[i] = new Vector3(origin.X + (6f * MathF.Cos(angle)), origin.Y + (6f * MathF.Sin(angle)), z);
                    }

                    AddFan(triangles, v);
                    break;
            }
        }

        return ([.. triangles], levels, kind switch { 0 => "whole-area stack", 1 => "rectangles and ramps", 2 => "stacked tiles", _ => "stacked fans" });
    }

    /// <summary>An axis-aligned rectangle from <paramref name="a"/> to <paramref name="b"/>, Z = <paramref name="z"/> at a plus slope · offset.</summary>
    private static void AddQuad(List<FloorTriangle> triangles, Vector2 a, Vector2 b, float z, Vector2 slope)
    {
        Vector3 At(float x, float y) => new(x, y, z + Vector2.Dot(slope, new Vector2(x, y) - a));
        AddFan(triangles, [At(a.X, a.Y), At(b.X, a.Y), At(b.X, b.Y), At(a.X, b.Y)]);
    }

    /// <summary>A convex counter-clockwise polygon, fan-triangulated as the cell does, with its plane when it has one.</summary>
    private static void AddFan(List<FloorTriangle> triangles, Vector3[] v)
    {
        FloorPlane? plane = FloorPlane.OfPolygon(v, Geometry.NewellNormal(v, v[0]));
        for (int i = 1; i + 1 < v.Length; i++)
        {
            if (FloorTriangle.TryCreate(v[0], v[i], v[i + 1], plane, out FloorTriangle triangle))
            {
                triangles.Add(triangle);
            }
        }
    }

    /// <summary><paramref name="floors"/> 10 m squares at cell-local (0..10, 0..10), Z = 0.25 m × index, the cell at (20, 30, 5).</summary>
    private static CellBuilder StackedCell(int floors)
    {
        var builder = new CellBuilder(0xA9B40100u, new Vector3(20f, 30f, 5f));
        for (int i = 0; i < floors; i++)
        {
            builder.Floor(0f, 0f, 10f, 10f, i * 0.25f);
        }

        return builder;
    }
}
