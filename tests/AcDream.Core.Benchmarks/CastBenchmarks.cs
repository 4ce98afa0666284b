using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.App.Fixtures;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Configs;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// The chase camera's cast (issue 21): from a pivot 1.5 m above the player's feet to an eye 2.5 m behind it and 0.75 m
/// up (2.61 m), a sphere of 0.3 m passing creatures, against a <see cref="MovementOptions.Player"/> <c>Resolve</c> of a
/// 2.61 m move from the same feet along the same heading (each category's baseline). Indoor: 1,024 starts on the 22 real
/// Holtburg cells where the player's body stands clear of every wall (<see cref="World.IndoorStart"/>). Outdoor: 1,024
/// starts 0.55–2 m from an object's bounds in the landblock of <see cref="ObjectResolveBenchmarks"/> (200 objects:
/// shells, stairs, trees), with 8 terrain-only neighbours.
/// </summary>
[MemoryDiagnoser]
[GroupBenchmarksBy(BenchmarkLogicalGroupRule.ByCategory)]
[CategoriesColumn]
public class CastCameraBenchmarks
{
    private const int Casts = 1024;
    private const float Back = 2.5f, Up = 0.75f, Pivot = 1.5f;
    private static readonly MovementOptions Player = MovementOptions.Player;
    private static readonly CastOptions Camera = new(0.3f, CastFilter.IgnoreCreatures | CastFilter.SolidOnly);

    private readonly Sample _indoor = new(), _outdoor = new();
    private PhysicsEngine _indoorEngine = null!, _outdoorEngine = null!;

    /// <summary>One place's starts, cells, headings: the move and the cast of each.</summary>
    private sealed class Sample
    {
        public readonly Vector3[] Feet = new Vector3[Casts];
        public readonly uint[] Cells = new uint[Casts];
        public readonly Vector3[] Moves = new Vector3[Casts];
        public readonly Vector3[] Pivots = new Vector3[Casts];
        public readonly Vector3[] Eyes = new Vector3[Casts];

        public void Set(int i, Vector3 feet, uint cell, float heading)
        {
            var forward = new Vector3(MathF.Cos(heading), MathF.Sin(heading), 0f);
            (Feet[i], Cells[i]) = (feet, cell);
            Pivots[i] = feet + new Vector3(0, 0, Pivot);
            Eyes[i] = Pivots[i] - (forward * Back) + new Vector3(0, 0, Up);
            Moves[i] = forward * Vector3.Distance(Pivots[i], Eyes[i]);
        }
    }

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        List<CellFixtureReader.FixtureCell> fixtures = World.HoltburgFixtures();
        List<CellSurface> surfaces = World.Surfaces(fixtures);
        List<World.WallFace> walls = World.Walls(fixtures);
        _indoorEngine = World.IndoorEngine(surfaces);
        int redrawn = 0;
        for (int i = 0; i < Casts; i++)
        {
            (Vector3 feet, uint cell) = World.IndoorStart(random, fixtures, surfaces, walls, ref redrawn);
            _indoor.Set(i, feet, cell, random.NextSingle() * MathF.Tau);
        }

        _outdoorEngine = new PhysicsEngine(World.Holtburg);
        float[] table = World.NonLinearTable();
        TerrainSurface centre = null!;
        List<ObjectSurface> objects = null!;
        foreach (uint id in World.Landblocks(9))
        {
            var terrain = new TerrainSurface(World.RollingHeights(random, 60, 6), table, id);
            if (centre is null)
            {
                centre = terrain;
                objects = ObjectWorld.Surfaces(ObjectWorld.Info(random, terrain), ObjectWorld.GfxObjs(), ObjectWorld.Setups());
                _outdoorEngine.AddLandblock(id, terrain, [], objects);
            }
            else
            {
                _outdoorEngine.AddLandblock(id, terrain, []);
            }
        }

        for (int n = 0; n < Casts;)
        {
            float x = (ObjectWorld.WestEdge - 2f) + (random.NextSingle() * (190f - ObjectWorld.WestEdge)), y = 1f + (random.NextSingle() * 190f);
            float d = ObjectWorld.DistanceToObjects(objects, new Vector2(x, y));
            if (d >= 0.55f && d <= 2f)
            {
                _outdoor.Set(n++, new Vector3(x, y, centre.SampleZ(x, y)), (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y), random.NextSingle() * MathF.Tau);
            }
        }

        Console.WriteLine($"// indoor: {redrawn} starts redrawn; camera pulled in {Pulled(_indoorEngine, _indoor)} of {Casts}; outdoor: {Pulled(_outdoorEngine, _outdoor)} of {Casts}");
    }

    private static int Pulled(PhysicsEngine engine, Sample s)
    {
        int n = 0;
        for (int i = 0; i < Casts; i++)
        {
            n += engine.Cast(s.Pivots[i], s.Cells[i], s.Eyes[i], in Camera).Hit ? 1 : 0;
        }

        return n;
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = Casts)]
    [BenchmarkCategory("Indoor")]
    public float Indoor_PlayerResolve() => Resolves(_indoorEngine, _indoor);

    [Benchmark(OperationsPerInvoke = Casts)]
    [BenchmarkCategory("Indoor")]
    public float Indoor_CameraCast() => CameraCasts(_indoorEngine, _indoor);

    [Benchmark(Baseline = true, OperationsPerInvoke = Casts)]
    [BenchmarkCategory("Outdoor")]
    public float Outdoor_PlayerResolve() => Resolves(_outdoorEngine, _outdoor);

    [Benchmark(OperationsPerInvoke = Casts)]
    [BenchmarkCategory("Outdoor")]
    public float Outdoor_CameraCast() => CameraCasts(_outdoorEngine, _outdoor);

    // One non-inlined loop per kind of call: every row runs the same machine code around its calls.
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static float Resolves(PhysicsEngine engine, Sample s)
    {
        float sum = 0f;
        for (int i = 0; i < Casts; i++)
        {
            ResolveResult r = engine.Resolve(s.Feet[i], s.Cells[i], s.Moves[i], World.PlayerStepUp, in Player);
            sum += r.Position.X + r.Position.Y;
        }

        return sum;
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static float CameraCasts(PhysicsEngine engine, Sample s)
    {
        float sum = 0f;
        for (int i = 0; i < Casts; i++)
        {
            CastHit h = engine.Cast(s.Pivots[i], s.Cells[i], s.Eyes[i], in Camera);
            sum += h.Position.X + h.Position.Y;
        }

        return sum;
    }
}

/// <summary>
/// A pointer's ray over terrain (issue 21): 1,024 rays from random points of the centre landblock's middle (x, y 60–132 m)
/// in random horizontal directions, 100 m (the baseline) and 200 m long, 0.5 m above the highest terrain of the 9
/// landblocks of rolling land they cross (so they meet nothing and walk every terrain cell under them, across seams); and
/// 100 m rays aimed down at the terrain at their end (they meet it on the way, except those that cross a seam where two
/// random landblocks' edge heights differ and pass through the step between them: the setup prints how many met it).
/// </summary>
[MemoryDiagnoser]
public class CastRayBenchmarks
{
    private const int Rays = 1024;
    private static readonly CastOptions Pointer = new(0f);
    private readonly Vector3[] _from = new Vector3[Rays];
    private readonly uint[] _cells = new uint[Rays];
    private readonly Vector3[] _to100 = new Vector3[Rays];
    private readonly Vector3[] _to200 = new Vector3[Rays];
    private readonly Vector3[] _groundFrom = new Vector3[Rays];
    private readonly Vector3[] _ground = new Vector3[Rays];
    private PhysicsEngine _engine = null!;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        float[] table = World.NonLinearTable();
        _engine = new PhysicsEngine(World.Holtburg);
        float top = float.MinValue;
        TerrainSurface centre = null!;
        foreach (uint id in World.Landblocks(9))
        {
            byte[] heights = World.RollingHeights(random, 60, 6);
            var terrain = new TerrainSurface(heights, table, id);
            _engine.AddLandblock(id, terrain, []);
            centre ??= terrain;
            top = MathF.Max(top, heights.Max(h => table[h]));
        }

        for (int i = 0; i < Rays; i++)
        {
            float x = 60f + (random.NextSingle() * 72f), y = 60f + (random.NextSingle() * 72f), heading = random.NextSingle() * MathF.Tau;
            var direction = new Vector3(MathF.Cos(heading), MathF.Sin(heading), 0f);
            _from[i] = new Vector3(x, y, top + 0.5f);
            _cells[i] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y);
            (_to100[i], _to200[i]) = (_from[i] + (direction * 100f), _from[i] + (direction * 200f));

            // Down at the ground 100 m away (the terrain there, read back from the neighbour's frame through the engine).
            Vector3 end = _to100[i];
            _engine.TryGetGround(end, 0, out float groundZ, out _);
            (_groundFrom[i], _ground[i]) = (_from[i] with { Z = groundZ + 30f }, end with { Z = groundZ - 0.5f });
        }

        int hit100 = 0, hit200 = 0, hitGround = 0;
        for (int i = 0; i < Rays; i++)
        {
            hit100 += _engine.Cast(_from[i], _cells[i], _to100[i], in Pointer).Hit ? 1 : 0;
            hit200 += _engine.Cast(_from[i], _cells[i], _to200[i], in Pointer).Hit ? 1 : 0;
            hitGround += _engine.Cast(_groundFrom[i], _cells[i], _ground[i], in Pointer).Kind == SurfaceKind.Terrain ? 1 : 0;
        }

        if (hit100 + hit200 != 0)
        {
            throw new InvalidOperationException($"{hit100} 100 m and {hit200} 200 m rays met something: they must cross the terrain clear.");
        }

        Console.WriteLine($"// rays 0.5 m over the highest ground at {top + 0.5f:F2} m: none met anything; down at the ground: {hitGround} of {Rays} met the terrain");
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = Rays)]
    public float Ray_100m() => Run(_engine, _from, _cells, _to100);

    [Benchmark(OperationsPerInvoke = Rays)]
    public float Ray_200m() => Run(_engine, _from, _cells, _to200);

    [Benchmark(OperationsPerInvoke = Rays)]
    public float Ray_100m_ToGround() => Run(_engine, _groundFrom, _cells, _ground);

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static float Run(PhysicsEngine engine, Vector3[] from, uint[] cells, Vector3[] to)
    {
        float sum = 0f;
        for (int i = 0; i < Rays; i++)
        {
            CastHit h = engine.Cast(from[i], cells[i], to[i], in Pointer);
            sum += h.Position.X + h.Position.Z;
        }

        return sum;
    }
}

/// <summary>
/// A long cast near many movers (issue 29): 256 rays 150 m east over one flat landblock, 1 m over the ground at y 71–73 m
/// (the baseline: no movers), past 10,000 and 100,000 creatures (cylinders 0.3 × 1.8 m) standing over local 0..150 ×
/// 0..150 m with none in y 69..75 m, and the same past 100,000 as a 0.3 m sphere and as a ray over their heads. Every cast
/// meets nothing (the setup throws otherwise): it pays only for the movers near its path, of which there are none.
/// </summary>
[MemoryDiagnoser]
public class CastMoverBenchmarks
{
    private const int Casts = 256;
    private readonly Vector3[] _from = new Vector3[Casts], _to = new Vector3[Casts], _overFrom = new Vector3[Casts], _overTo = new Vector3[Casts];
    private PhysicsEngine _none = null!, _ten = null!, _hundred = null!;

    [GlobalSetup]
    public void Setup()
    {
        (_none, _ten, _hundred) = (Flat(0), Flat(10_000), Flat(100_000));
        Vector3 o = _none.GetLandblockOrigin(World.Holtburg);
        var random = new Random(29);
        for (int i = 0; i < Casts; i++)
        {
            float y = 71f + (random.NextSingle() * 2f);
            (_from[i], _to[i]) = (o + new Vector3(1f, y, 51f), o + new Vector3(151f, y, 51f));
            (_overFrom[i], _overTo[i]) = (_from[i] + new Vector3(0f, 0f, 2f), _to[i] + new Vector3(0f, 0f, 2f));
        }

        foreach (PhysicsEngine engine in new[] { _none, _ten, _hundred })
        {
            for (int i = 0; i < Casts; i++)
            {
                if (engine.Cast(_from[i], 0, _to[i], new CastOptions(0.3f)).Hit || engine.Cast(_overFrom[i], 0, _overTo[i], new CastOptions(0f)).Hit)
                {
                    throw new InvalidOperationException($"cast {i} met something: the path must be clear.");
                }
            }
        }
    }

    /// <summary>One flat landblock (ground at 50 m) with <paramref name="count"/> creatures over local 0..150 × 0..150 m, none in y 69..75 m.</summary>
    private static PhysicsEngine Flat(int count)
    {
        var engine = new PhysicsEngine(World.Holtburg);
        engine.AddLandblock(World.Holtburg, new TerrainSurface(new byte[81], Enumerable.Repeat(50f, 256).ToArray(), World.Holtburg), []);
        Vector3 o = engine.GetLandblockOrigin(World.Holtburg);
        var random = new Random(5);
        MoverShape creature = MoverShape.Cylinder(0.3f, 1.8f);
        for (uint id = 1; id <= count;)
        {
            float x = random.NextSingle() * 150f, y = random.NextSingle() * 150f;
            if (y < 69f || y > 75f)
            {
                engine.Movers.Add(id++, creature, o + new Vector3(x, y, 50f), (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y), Quaternion.Identity, MoverState.Creature);
            }
        }

        engine.Movers.Commit();
        return engine;
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = Casts)]
    public float Ray_NoMovers() => Run(_none, _from, _to, 0f);

    [Benchmark(OperationsPerInvoke = Casts)]
    public float Ray_10000Movers() => Run(_ten, _from, _to, 0f);

    [Benchmark(OperationsPerInvoke = Casts)]
    public float Ray_100000Movers() => Run(_hundred, _from, _to, 0f);

    [Benchmark(OperationsPerInvoke = Casts)]
    public float Sphere_NoMovers() => Run(_none, _from, _to, 0.3f);

    [Benchmark(OperationsPerInvoke = Casts)]
    public float Sphere_100000Movers() => Run(_hundred, _from, _to, 0.3f);

    [Benchmark(OperationsPerInvoke = Casts)]
    public float RayOverHeads_NoMovers() => Run(_none, _overFrom, _overTo, 0f);

    [Benchmark(OperationsPerInvoke = Casts)]
    public float RayOverHeads_100000Movers() => Run(_hundred, _overFrom, _overTo, 0f);

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static float Run(PhysicsEngine engine, Vector3[] from, Vector3[] to, float radius)
    {
        var options = new CastOptions(radius);
        float sum = 0f;
        for (int i = 0; i < Casts; i++)
        {
            CastHit h = engine.Cast(from[i], 0, to[i], in options);
            sum += h.Position.X + h.Position.Y;
        }

        return sum;
    }
}
