using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Seeded property tests: random heightmaps, height tables, floor polygons and cells against slow
/// double-precision references and the engine's invariants. A failure prints its seed and inputs.
/// </summary>
public class RandomisedInvariantTests
{
    [Theory]
    [InlineData(101)]
    [InlineData(202)]
    public void SampleZ_RetailTerrain_MatchesDoubleReference(int seed)
    {
        var random = new Random(seed);
        int checkedPoints = 0;
        for (int n = 0; n < 300; n++)
        {
            byte[] heights = Gen.Heights(random);
            float[] table = Gen.HeightTable(random);
            int lbX = random.Next(4) switch { 0 => 0x00, 1 => 0xFE, _ => random.Next(255) };
            int lbY = random.Next(4) switch { 0 => 0x00, 1 => 0xFE, _ => random.Next(255) };
            uint id = ((uint)lbX << 24) | ((uint)lbY << 16) | 0xFFFFu;
            var terrain = new TerrainSurface(heights, table, id);
            for (int k = 0; k < 30; k++)
            {
                (float x, float y) = (k % 6) switch
                {
                    0 => (24f * random.Next(9), Gen.Range(random, 0, 192)),               // on a cell edge
                    1 => (24f * random.Next(9), 24f * random.Next(9)),                     // on a vertex
                    2 => Diagonal(random, swToNe: true),
                    3 => Diagonal(random, swToNe: false),
                    4 => (Gen.Range(random, -20, 212), Gen.Range(random, -20, 212)),     // clamps outside
                    _ => (Gen.Range(random, 0, 192), Gen.Range(random, 0, 192)),
                };

                double expected = Reference.TerrainZ(heights, table, lbX, lbY, x, y);
                float actual = terrain.SampleZ(x, y);
                Math.Abs(actual - expected).Should().BeLessThan(1e-4,
                    $"seed {seed}, terrain {n} (0x{id:X8}, table[0] {table[0]}, table[255] {table[255]}), point {k} ({x:R}, {y:R}): engine {actual:R}, reference {expected:R}");
                checkedPoints++;
            }
        }

        checkedPoints.Should().Be(9000);

        static (float, float) Diagonal(Random random, bool swToNe)
        {
            // A point on a cell diagonal, exact in float (a multiple of 1/64 along it).
            int cx = random.Next(8), cy = random.Next(8);
            float t = random.Next(0, 24 * 64 + 1) / 64f;
            return swToNe ? ((24f * cx) + t, (24f * cy) + t) : ((24f * cx) + t, (24f * (cy + 1)) - t);
        }
    }

    [Theory]
    [InlineData(303)]
    [InlineData(404)]
    public void SampleFloorZ_RandomCells_MatchesBruteForceReference(int seed)
    {
        var random = new Random(seed);
        int compared = 0, skipped = 0;
        for (int n = 0; n < 400; n++)
        {
            uint cellId = 0x00FE0100u + (uint)random.Next(0xFD00);
            var origin = new Vector3(Gen.Range(random, -50, 250), Gen.Range(random, -50, 250), Gen.Range(random, -60, 160));
            Quaternion orientation = Gen.Orientation(random, sloppy: random.Next(2) == 0);
            var builder = new CellBuilder(cellId, origin, orientation);
            int polygons = random.Next(1, 13);
            for (int p = 0; p < polygons; p++)
            {
                builder.Physics(Gen.Polygon(random, 8));
            }

            CellSurface cell = builder.Build();
            List<Reference.Triangle> triangles = Reference.FloorTriangles(builder.EnvCell, builder.CellStruct);
            for (int k = 0; k < 30; k++)
            {
                double x, y;
                if (k % 3 == 0 && triangles.Count > 0)
                {
                    // On a triangle's vertex or edge: the seams between triangles.
                    Reference.Triangle t = triangles[random.Next(triangles.Count)];
                    double s = random.Next(3) == 0 ? 0 : random.NextDouble();
                    (x, y) = random.Next(2) == 0 ? (t.A.X + (s * (t.B.X - t.A.X)), t.A.Y + (s * (t.B.Y - t.A.Y))) : (t.B.X + (s * (t.C.X - t.B.X)), t.B.Y + (s * (t.C.Y - t.B.Y)));
                }
                else
                {
                    Vector3 local = new(Gen.Range(random, -10, 10), Gen.Range(random, -10, 10), 0);
                    Vector3 p = origin + Vector3.Transform(local, Quaternion.Normalize(orientation));
                    (x, y) = (p.X, p.Y);
                }

                float fx = (float)x, fy = (float)y, referenceZ = Gen.Range(random, origin.Z - 10, origin.Z + 10);
                (List<double> zs, bool ambiguous, bool nearEdge) = Reference.FloorZs(triangles, fx, fy, margin: 1e-4);
                if (ambiguous)
                {
                    skipped++;
                    continue;
                }

                string what = $"seed {seed}, cell {n} (origin {origin}, orientation {orientation}, {polygons} polygons, {triangles.Count} triangles), query {k} at ({fx:R}, {fy:R}), reference Z {referenceZ:R}";
                float? top = cell.SampleFloorZ(fx, fy);
                float? nearest = cell.SampleFloorZ(fx, fy, referenceZ);
                if (zs.Count == 0)
                {
                    top.Should().BeNull(what);
                    nearest.Should().BeNull(what);
                }
                else
                {
                    double tolerance = nearEdge ? 5e-4 : 1e-4;
                    top.Should().NotBeNull(what);
                    Math.Abs(top!.Value - zs.Max()).Should().BeLessThan(tolerance, $"topmost floor: {what}; reference Zs {string.Join(", ", zs)}");
                    double best = zs.OrderBy(z => Math.Abs(z - referenceZ)).ThenByDescending(z => z).First();
                    double runnerUp = zs.Where(z => Math.Abs(z - best) > tolerance).Select(z => Math.Abs(z - referenceZ)).DefaultIfEmpty(double.MaxValue).Min();
                    if (runnerUp - Math.Abs(best - referenceZ) > 2 * tolerance)
                    {
                        Math.Abs(nearest!.Value - best).Should().BeLessThan(tolerance, $"nearest floor: {what}; reference Zs {string.Join(", ", zs)}");
                    }
                }

                compared++;
            }
        }

        compared.Should().BeGreaterThan(11_500, $"seed {seed}: at most a few of 12,000 queries sit within 0.1 mm of the tolerance boundary ({skipped} skipped)");
    }

    [Theory]
    [InlineData(505)]
    [InlineData(606)]
    public void Resolve_RandomWorlds_OutputsFiniteOnTheSurfaceAndWithinStepHeight(int seed)
    {
        var random = new Random(seed);
        int moves = 0;
        for (int w = 0; w < 12; w++)
        {
            int lbX = random.Next(3) switch { 0 => 0x00, 1 => 0xFE, _ => random.Next(1, 254) };
            int lbY = random.Next(3) switch { 0 => 0x00, 1 => 0xFE, _ => random.Next(1, 254) };
            uint id = ((uint)lbX << 24) | ((uint)lbY << 16) | 0xFFFFu;
            bool global = random.Next(2) == 0;
            var engine = global ? new PhysicsEngine() : new PhysicsEngine(id);
            byte[] heights = Gen.Heights(random);
            float[] table = Gen.HeightTable(random);
            var cells = new List<CellSurface>();
            for (int c = 0; c < 6; c++)
            {
                var origin = new Vector3(Gen.Range(random, 10, 182), Gen.Range(random, 10, 182), Gen.Range(random, -50, 300));
                var builder = new CellBuilder((id & 0xFFFF0000u) | (uint)(0x0100 + c), origin, Gen.Orientation(random, sloppy: true));
                for (int p = random.Next(1, 6); p > 0; p--)
                {
                    builder.Physics(Gen.Polygon(random, 6));
                }

                builder.Portal((ushort)(0x0100 + random.Next(6)), new Vector3(0, 0, 1), Wall(-3, -3, -3, 3, -1, 3));
                builder.Portal(0xFFFF, new Vector3(0, 0, 1), Wall(3, 3, 3, -3, -1, 3));
                cells.Add(builder.Build());
            }

            var terrain = new TerrainSurface(heights, table, id);
            engine.AddLandblock(id, terrain, cells);
            Vector3 offset = engine.GetLandblockOrigin(id);
            float spacing = MathF.BitIncrement(MathF.Max(MathF.Abs(offset.X), MathF.Abs(offset.Y)) + 192f) - (MathF.Max(MathF.Abs(offset.X), MathF.Abs(offset.Y)) + 192f);
            double gradient = Reference.MaxGradient(heights, table);

            for (int m = 0; m < 1000; m++)
            {
                bool indoor = m % 3 == 2;
                CellSurface? start = indoor ? cells[random.Next(cells.Count)] : null;
                var local = new Vector2(Gen.Range(random, 0, 192), Gen.Range(random, 0, 192));
                if (start is not null)
                {
                    local = new Vector2(start.Origin.X, start.Origin.Y) + new Vector2(Gen.Range(random, -6, 6), Gen.Range(random, -6, 6));
                }

                float ground = start is null ? terrain.SampleZ(local.X, local.Y) : start.SampleFloorZ(local.X, local.Y, start.Origin.Z) ?? start.Origin.Z;
                var pos = new Vector3(offset.X + local.X, offset.Y + local.Y, ground + Gen.Range(random, random.Next(4) == 0 ? -2 : 0, 1));
                uint cellId = start?.CellId ?? (id & 0xFFFF0000u) | (uint)random.Next(0, 0x41);
                var delta = new Vector3(Gen.Range(random, -4, 4) * (random.Next(5) == 0 ? 60 : 1), Gen.Range(random, -4, 4), Gen.Range(random, -9, 9));
                float step = random.Next(5) == 0 ? 0f : Gen.Range(random, 0, 3);
                string what = $"seed {seed}, world {w} (0x{id:X8}, {(global ? "global" : "centred")}), move {m}: {pos:R} in 0x{cellId:X8} by {delta:R}, step {step:R}";

                ResolveResult r = engine.Resolve(pos, cellId, delta, step);
                moves++;

                float.IsFinite(r.Position.X).Should().BeTrue(what);
                float.IsFinite(r.Position.Y).Should().BeTrue(what);
                float.IsFinite(r.Position.Z).Should().BeTrue(what);
                Vector2 resultLocal = new Vector2(r.Position.X, r.Position.Y) - new Vector2(offset.X, offset.Y);
                if (r.Position == pos || !r.IsOnGround)
                {
                    continue; // rejected (kept in place, or airborne above its ground) or held: nothing moved
                }

                // Never more than the step height above where the mover stood (or the ground under it, if it
                // had sunk), sampled where the mover really stood: its world position's landblock-local point.
                Vector2 stood = new Vector2(pos.X, pos.Y) - new Vector2(offset.X, offset.Y);
                float groundUnder = start is null ? terrain.SampleZ(stood.X, stood.Y) : start.SampleFloorZ(stood.X, stood.Y, pos.Z) ?? float.NegativeInfinity;
                (r.Position.Z - MathF.Max(pos.Z, groundUnder)).Should().BeLessThanOrEqualTo(step + 1e-4f, $"rise: {what} → {r}");

                if ((r.CellId & 0xFFFF) < 0x100)
                {
                    if ((r.CellId & 0xFFFF0000u) == (id & 0xFFFF0000u) && resultLocal.X is >= 0 and <= 192 && resultLocal.Y is >= 0 and <= 192)
                    {
                        // Exactly on the terrain, up to the rounding of the world position (see docs/hard-cases.md).
                        double bound = 1e-4 + (gradient * spacing);
                        Math.Abs((double)r.Position.Z - terrain.SampleZ(resultLocal.X, resultLocal.Y)).Should().BeLessThan(bound, $"on terrain: {what} → {r}");
                    }
                }
                else
                {
                    CellSurface landed = cells.Single(c => c.CellId == r.CellId);
                    float? floor = landed.SampleFloorZ(resultLocal.X, resultLocal.Y, r.Position.Z);
                    floor.Should().NotBeNull($"on a floor: {what} → {r}");
                    if (!global)
                    {
                        Math.Abs(r.Position.Z - floor!.Value).Should().BeLessThan(1e-4f, $"on the floor: {what} → {r}");
                    }
                }
            }
        }

        moves.Should().Be(12_000);
    }
}
