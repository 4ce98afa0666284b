using System.Globalization;
using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// <c>--accuracy</c>, casts: the chase camera's sphere and random rays and spheres in the 22 real Holtburg cells, and
/// 200 m rays onto rolling land across seams, against <see cref="CastReference"/> (double precision, from the geometric
/// definition) in the frame centred on Holtburg. Seeded (5); about a minute (the reference is slow).
/// </summary>
internal static class CastAccuracy
{
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    public static void Run(TextWriter o)
    {
        o.WriteLine("## Casts");
        o.WriteLine();
        o.WriteLine("`PhysicsEngine.Cast` against `tests/Shared/CastReference.cs` (the first fraction at which the distance from the");
        o.WriteLine("sphere's centre to any shape falls to its radius, found by advancing by that distance and bisecting, in double");
        o.WriteLine("precision), centred on Holtburg. Travel is the fraction times the segment's length; a disagreement is a cast");
        o.WriteLine("one of the two says met something and the other not, or that differs by more than 1e-4 m. Left out: casts that start");
        o.WriteLine("within their radius of a surface (the reference meets it at 0 whichever way they go; the engine only when they move");
        o.WriteLine("into it) and casts that leave the cells through a doorway (this reference holds the cells, not the ground outside;");
        o.WriteLine("`CastDoorwayTests` compares those).");
        o.WriteLine();
        o.WriteLine("| casts | compared | left out | met something | disagreements | max \\|travel − reference\\| | mean |");
        o.WriteLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: |");
        var random = new Random(5);
        Indoors(o, random);
        Terrain(o, random);
        o.WriteLine();
    }

    private static void Indoors(TextWriter o, Random random)
    {
        List<CellFixtureReader.FixtureCell> fixtures = World.HoltburgFixtures();
        List<CellSurface> surfaces = World.Surfaces(fixtures);
        List<World.WallFace> walls = World.Walls(fixtures);
        PhysicsEngine engine = World.IndoorEngine(surfaces);
        var cells = fixtures.Select(f => (f.CellId, f.EnvCell, f.CellStruct)).ToList();
        var reference = new CastReference([.. cells.SelectMany(c => Cell(c.CellId, c.EnvCell, c.CellStruct)), .. MissingPortals(cells)]);
        Tally camera = new(), rays = new(), spheres = new();
        int redrawn = 0;
        for (int i = 0; i < 400; i++)
        {
            (Vector3 feet, uint cell) = World.IndoorStart(random, fixtures, surfaces, walls, ref redrawn);
            Vector3 pivot = feet + new Vector3(0f, 0f, 1.5f);
            float heading = random.NextSingle() * MathF.Tau;
            Vector3 eye = pivot + new Vector3(-MathF.Cos(heading) * 2.5f, -MathF.Sin(heading) * 2.5f, 0.75f);
            camera.Add(engine, reference, pivot, cell, eye, 0.3f);

            // A ray and a sphere of 0.3 m from 1 m over the feet, 4 m in a random direction (up and down included).
            Vector3 from = feet + new Vector3(0f, 0f, 1f);
            Vector3 direction = Vector3.Normalize(new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, random.NextSingle() - 0.5f));
            rays.Add(engine, reference, from, cell, from + (direction * 4f), 0f);
            spheres.Add(engine, reference, from, cell, from + (direction * 4f), 0.3f);
        }

        camera.Write(o, "the chase camera in the real cells (0.3 m sphere, pivot 1.5 m over the feet, 2.61 m boom)");
        rays.Write(o, "rays in the real cells (4 m from 1 m over the feet, random directions)");
        spheres.Write(o, "spheres of 0.3 m in the real cells (the same casts)");
    }

    private static void Terrain(TextWriter o, Random random)
    {
        // Rolling land shared along every seam (a function of the global vertex), 3 × 3 landblocks around Holtburg.
        const int cx = 0xA9, cy = 0xB4;
        var engine = new PhysicsEngine(World.Holtburg);
        var shapes = new List<Shape>();
        float[] table = World.NonLinearTable();
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                var heights = new byte[81];
                for (int x = 0; x < 9; x++)
                {
                    for (int y = 0; y < 9; y++)
                    {
                        int gx = ((cx + dx) * 8) + x, gy = ((cy + dy) * 8) + y;
                        heights[(x * 9) + y] = (byte)(60 + (int)(6 * Math.Sin(gx * 0.9)) + (int)(5 * Math.Cos(gy * 0.7)));
                    }
                }

                uint id = World.LandblockId(cx + dx, cy + dy);
                engine.AddLandblock(id, new TerrainSurface(heights, table, id), []);
                shapes.AddRange(CastReference.Terrain([.. heights.Select(h => (double)table[h])], cx + dx, cy + dy, new V3(dx * 192.0, dy * 192.0, 0)));
            }
        }

        var reference = new CastReference(shapes);
        Tally rays = new(), spheres = new();
        for (int i = 0; i < 60; i++)
        {
            float x = 40f + (random.NextSingle() * 112f), y = 40f + (random.NextSingle() * 112f), heading = random.NextSingle() * MathF.Tau;
            Vector3 end = new Vector3(x + (MathF.Cos(heading) * 200f), y + (MathF.Sin(heading) * 200f), 0f);
            engine.TryGetGround(end, 0, out float ground, out _);
            engine.TryGetGround(new Vector3(x, y, 0f), 0, out float start, out _);
            var from = new Vector3(x, y, start + 20f);
            var to = end with { Z = ground - 1f };
            rays.Add(engine, reference, from, 0, to, 0f, indoors: false);
            spheres.Add(engine, reference, from, 0, to, 0.3f, indoors: false);
        }

        rays.Write(o, "rays of 200 m onto rolling land across seams (from 20 m up to 1 m under the ground at their end)");
        spheres.Write(o, "spheres of 0.3 m, the same casts");
    }

    /// <summary>The running comparison of one kind of cast.</summary>
    private sealed class Tally
    {
        private int _compared, _met, _disagree, _left;
        private double _max, _sum;

        public void Add(PhysicsEngine engine, CastReference reference, Vector3 from, uint cell, Vector3 to, float radius, bool indoors = true)
        {
            CastHit hit = engine.Cast(from, cell, to, new CastOptions(radius));
            Vector3 origin = engine.GetLandblockOrigin(World.Holtburg);
            V3 a = V3.Of(from - origin), b = V3.Of(to - origin);
            Hit? expected = reference.Cast(a, b, radius);
            double length = (b - a).Length;
            if (expected is { Overlapping: true } || (indoors && CellIds.IsOutdoor(hit.CellId)))
            {
                _left++; // a start within the radius of a surface (the reference meets it at 0 whichever way the cast goes; the engine only moving into it), or a cast out of the cells (the reference holds no terrain)
                return;
            }

            _compared++;
            bool engineMet = hit.Hit && hit.Kind != SurfaceKind.None;
            if (engineMet != (expected is not null))
            {
                _disagree++;
                return;
            }

            if (expected is null)
            {
                return;
            }

            _met++;
            double error = Math.Abs((hit.Fraction * length) - (expected.T * length));
            (_max, _sum) = (Math.Max(_max, error), _sum + error);
            _disagree += error > 1e-4 ? 1 : 0;
        }

        public void Write(TextWriter o, string what) =>
            o.WriteLine(string.Format(Inv, "| {0} | {1} | {2} | {3} | {4} | {5:0.0e+0} m | {6:0.0e+0} m |", what, _compared, _left, _met, _disagree, _max, _met == 0 ? 0 : _sum / _met));
    }
}
