using System.Numerics;
using System.Runtime.CompilerServices;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Configs;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Registering a landblock with <see cref="ObjectWorld.ObjectCount"/> objects (issue 11: five real
/// building shells, three staircases of the real stair piece, trees as Setups with a cylinder and a
/// box part; <see cref="ObjectWorld.Info"/>), building their <see cref="ObjectSurface"/>s from the dat
/// model, against the baseline: the 16 real cottage cells' surfaces built and added
/// (<see cref="AddLandblockBenchmarks.BuildAndAdd"/>, the same code). Target: ≤ 40×.
/// </summary>
[MemoryDiagnoser]
public class ObjectAddLandblockBenchmarks
{
    private List<CellFixtureReader.FixtureCell> _fixtures = null!;
    private byte[] _heights = null!;
    private float[] _table = null!;
    private LandBlockInfo _info = null!;
    private Dictionary<uint, GfxObj> _gfxObjs = null!;
    private Dictionary<uint, Setup> _setups = null!;
    private List<ObjectSurface> _objects = null!;
    private TerrainSurface _terrain = null!;
    private PhysicsEngine _engine = null!;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        _fixtures = World.HoltburgFixtures().Take(16).ToList();
        _heights = World.RollingHeights(random, 60, 6);
        _table = World.NonLinearTable();
        _terrain = new TerrainSurface(_heights, _table, World.Holtburg);
        _gfxObjs = ObjectWorld.GfxObjs();
        _setups = ObjectWorld.Setups();
        _info = ObjectWorld.Info(random, _terrain);
        _objects = ObjectWorld.Surfaces(_info, _gfxObjs, _setups);
        _engine = new PhysicsEngine(World.Holtburg);
        int polygons = _objects.Sum(o => o.GetWalls().Length + o.GetFloorTriangles().Length);
        Console.WriteLine($"// {_objects.Count} objects ({_info.Buildings.Count} buildings, {_info.Objects.Count} stabs): {polygons} wall polygons, cylinders and floor triangles");
    }

    /// <summary>The 16 real cottage cells: their surfaces built from the dat model and added (<see cref="AddLandblockBenchmarks.BuildAndAdd"/>).</summary>
    [Benchmark(Baseline = true)]
    public int CellsBuildAndAdd() => AddLandblockBenchmarks.BuildAndAdd(_engine, _fixtures, _heights, _table);

    /// <summary>The 200 objects: their surfaces built from the landblock's object list (<see cref="ObjectSurface.FromLandblock"/>) and added with the terrain.</summary>
    [Benchmark]
    public int ObjectsBuildAndAdd()
    {
        List<ObjectSurface> objects = ObjectSurface.FromLandblock(World.Holtburg, _info, [], _gfxObjs, _setups);
        _engine.AddLandblock(World.Holtburg, new TerrainSurface(_heights, _table, World.Holtburg), [], objects);
        return _engine.LandblockCount;
    }

    /// <summary>Building the 200 objects' surfaces alone.</summary>
    [Benchmark]
    public int ObjectsBuildOnly() => ObjectSurface.FromLandblock(World.Holtburg, _info, [], _gfxObjs, _setups).Count;

    /// <summary>Adding the prebuilt objects (and terrain) alone: the per-outdoor-cell object buckets.</summary>
    [Benchmark]
    public int ObjectsAddOnly()
    {
        _engine.AddLandblock(World.Holtburg, _terrain, [], _objects);
        return _engine.LandblockCount;
    }
}

/// <summary>
/// Outdoor <c>Resolve</c> among objects (issue 11): the benchmark landblock of
/// <see cref="ObjectAddLandblockBenchmarks"/> (Holtburg, rolling terrain, 8 terrain-only neighbours)
/// with its 200 objects, against the same world without them (each category's baseline), for the
/// literal call and <see cref="MovementOptions.Player"/>. <c>Near</c>: 1,024 random 0.1–0.3 m moves
/// starting 0.55–2 m from an object's bounding box (so the player's body starts clear of it) and
/// outside every one; <c>Far</c>: 1,024 in the west of the landblock (x &lt; 86 m), where no object's
/// bounds reach (the setup checks that they answer bit for bit as without objects).
/// </summary>
[MemoryDiagnoser]
[GroupBenchmarksBy(BenchmarkLogicalGroupRule.ByCategory)]
[CategoriesColumn]
public class ObjectResolveBenchmarks
{
    private const int Moves = 1024;

    private static readonly MovementOptions Player = MovementOptions.Player;

    private readonly Vector3[] _near = new Vector3[Moves];
    private readonly uint[] _nearCells = new uint[Moves];
    private readonly Vector3[] _nearDeltas = new Vector3[Moves];
    private readonly Vector3[] _far = new Vector3[Moves];
    private readonly uint[] _farCells = new uint[Moves];
    private readonly Vector3[] _farDeltas = new Vector3[Moves];
    private PhysicsEngine _objects = null!;
    private PhysicsEngine _bare = null!;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        float[] table = World.NonLinearTable();
        _objects = new PhysicsEngine(World.Holtburg);
        _bare = new PhysicsEngine(World.Holtburg);
        TerrainSurface centre = null!;
        List<ObjectSurface> objects = null!;
        foreach (uint id in World.Landblocks(9))
        {
            var terrain = new TerrainSurface(World.RollingHeights(random, 60, 6), table, id);
            _bare.AddLandblock(id, terrain, []);
            if (centre is null)
            {
                centre = terrain;
                objects = ObjectWorld.Surfaces(ObjectWorld.Info(random, terrain), ObjectWorld.GfxObjs(), ObjectWorld.Setups());
                _objects.AddLandblock(id, terrain, [], objects);
            }
            else
            {
                _objects.AddLandblock(id, terrain, []);
            }
        }

        for (int n = 0; n < Moves;)
        {
            float x = (ObjectWorld.WestEdge - 2f) + (random.NextSingle() * (190f - ObjectWorld.WestEdge)), y = 1f + (random.NextSingle() * 190f);
            float d = ObjectWorld.DistanceToObjects(objects, new Vector2(x, y));
            if (d >= 0.55f && d <= 2f)
            {
                _near[n] = new Vector3(x, y, centre.SampleZ(x, y));
                _nearCells[n] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y);
                _nearDeltas[n] = World.RandomDelta(random, 0.1f, 0.3f);
                n++;
            }
        }

        for (int n = 0; n < Moves; n++)
        {
            float x = 4f + (random.NextSingle() * 82f), y = 4f + (random.NextSingle() * 184f);
            _far[n] = new Vector3(x, y, centre.SampleZ(x, y));
            _farCells[n] = (World.Holtburg & 0xFFFF0000u) | World.OutdoorCell(x, y);
            _farDeltas[n] = World.RandomDelta(random, 0.1f, 0.3f);
        }

        int farDiffer = 0, nearDiffer = 0, nearPlayerDiffer = 0;
        for (int i = 0; i < Moves; i++)
        {
            farDiffer += _objects.Resolve(_far[i], _farCells[i], _farDeltas[i], World.PlayerStepUp) != _bare.Resolve(_far[i], _farCells[i], _farDeltas[i], World.PlayerStepUp) ? 1 : 0;
            farDiffer += _objects.Resolve(_far[i], _farCells[i], _farDeltas[i], World.PlayerStepUp, in Player) != _bare.Resolve(_far[i], _farCells[i], _farDeltas[i], World.PlayerStepUp, in Player) ? 1 : 0;
            nearDiffer += _objects.Resolve(_near[i], _nearCells[i], _nearDeltas[i], World.PlayerStepUp) != _bare.Resolve(_near[i], _nearCells[i], _nearDeltas[i], World.PlayerStepUp) ? 1 : 0;
            nearPlayerDiffer += _objects.Resolve(_near[i], _nearCells[i], _nearDeltas[i], World.PlayerStepUp, in Player) != _bare.Resolve(_near[i], _nearCells[i], _nearDeltas[i], World.PlayerStepUp, in Player) ? 1 : 0;
        }

        if (farDiffer != 0)
        {
            throw new InvalidOperationException($"{farDiffer} far moves answer differently with the objects.");
        }

        Console.WriteLine($"// near moves: {nearDiffer} of {Moves} literal and {nearPlayerDiffer} Player answers differ from those without objects; outcomes with objects, literal: {Outcomes(_objects, _near, _nearCells, _nearDeltas, default)}; Player: {Outcomes(_objects, _near, _nearCells, _nearDeltas, Player)}; without objects, Player: {Outcomes(_bare, _near, _nearCells, _nearDeltas, Player)}");
        Console.WriteLine($"// far moves: all {2 * Moves} answers (literal, Player) identical with and without objects");
    }

    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Near, literal")]
    public float Near_Literal_NoObjects() => Literal(_bare, _near, _nearCells, _nearDeltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Near, literal")]
    public float Near_Literal() => Literal(_objects, _near, _nearCells, _nearDeltas);

    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Near, Player")]
    public float Near_Player_NoObjects() => Run(_bare, _near, _nearCells, _nearDeltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Near, Player")]
    public float Near_Player() => Run(_objects, _near, _nearCells, _nearDeltas);

    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Far, literal")]
    public float Far_Literal_NoObjects() => Literal(_bare, _far, _farCells, _farDeltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Far, literal")]
    public float Far_Literal() => Literal(_objects, _far, _farCells, _farDeltas);

    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Far, Player")]
    public float Far_Player_NoObjects() => Run(_bare, _far, _farCells, _farDeltas);

    [Benchmark(OperationsPerInvoke = Moves)]
    [BenchmarkCategory("Far, Player")]
    public float Far_Player() => Run(_objects, _far, _farCells, _farDeltas);

    // The loops are compiled once, not into each benchmark method: every row then runs the same
    // machine code around its calls (inlined, each row's loop was laid out on its own, and rows with
    // the same work differed by up to 20 % on this VM).
    [MethodImpl(MethodImplOptions.NoInlining)]
    private static float Literal(PhysicsEngine engine, Vector3[] positions, uint[] cells, Vector3[] deltas)
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += Sum(engine.Resolve(positions[i], cells[i], deltas[i], World.PlayerStepUp));
        }

        return sum;
    }

    [MethodImpl(MethodImplOptions.NoInlining)]
    private static float Run(PhysicsEngine engine, Vector3[] positions, uint[] cells, Vector3[] deltas)
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += Sum(engine.Resolve(positions[i], cells[i], deltas[i], World.PlayerStepUp, in Player));
        }

        return sum;
    }

    private static string Outcomes(PhysicsEngine engine, Vector3[] positions, uint[] cells, Vector3[] deltas, MovementOptions options)
    {
        var counts = new SortedDictionary<ResolveOutcome, int>();
        for (int i = 0; i < Moves; i++)
        {
            ResolveOutcome outcome = engine.Resolve(positions[i], cells[i], deltas[i], World.PlayerStepUp, in options).Outcome;
            counts[outcome] = counts.GetValueOrDefault(outcome) + 1;
        }

        return string.Join(", ", counts.Select(kv => $"{kv.Key} {kv.Value}"));
    }

    private static float Sum(ResolveResult r) => r.Position.X + r.Position.Z + r.CellId + (r.IsOnGround ? 1f : 0f);
}
