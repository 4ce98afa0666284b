using System.Numerics;
using AcDream.App.Streaming;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Environment = AcDream.Core.Dat.Environment;

namespace AcDream.App.Tests;

/// <summary>Small builders for terrain, cells and landblock sources.</summary>
internal static class TestWorlds
{
    public const uint Holtburg = 0xA9B4FFFFu;

    /// <summary>The repository's root: the first folder above the test binaries that holds AcDream.sln.</summary>
    public static string RepositoryRoot()
    {
        for (DirectoryInfo? dir = new(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            if (File.Exists(Path.Combine(dir.FullName, "AcDream.sln")))
            {
                return dir.FullName;
            }
        }

        throw new InvalidOperationException($"AcDream.sln not found above {AppContext.BaseDirectory}");
    }

    /// <summary>Table entry i = i metres.</summary>
    public static float[] LinearTable() => Enumerable.Range(0, 256).Select(i => (float)i).ToArray();

    /// <summary>Height indices from a function of the vertex indices (x, y), x-major.</summary>
    public static byte[] Heights(Func<int, int, int> height) => CellBuilder.Heights(height);

    /// <summary>An engine centred on Holtburg with one landblock of terrain (linear table: index = metres) and the given cells.</summary>
    public static PhysicsEngine Engine(byte[] heights, params CellSurface[] cells)
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, new TerrainSurface(heights, LinearTable(), Holtburg), cells);
        return engine;
    }

    /// <summary>A horizontal square, counter-clockwise seen from above (normal +Z), cell-local.</summary>
    public static Vector3[] Square(float half, float z) => CellBuilder.Square(-half, -half, half, half, z);

    /// <summary>
    /// A cell at landblock-local <paramref name="origin"/> (no rotation) with optional floor and
    /// horizontal portals (openings of the same square, to the cells named, at the heights given).
    /// </summary>
    public static CellSurface Cell(uint cellId, Vector3 origin, float? floorZ, params (ushort Other, float Z, bool CellAbove)[] openings)
    {
        var builder = new CellBuilder(cellId, origin);
        if (floorZ is float z)
        {
            builder.Physics(Square(5f, z));
        }

        foreach ((ushort other, float openingZ, bool cellAbove) in openings)
        {
            builder.Portal(other, new Vector3(0f, 0f, openingZ + (cellAbove ? 1f : -1f)), Square(2f, openingZ));
        }

        return builder.Build();
    }
}

/// <summary>Flat land everywhere (index 10), no cells; can fail the first load of chosen landblocks, can be slow, and records its calls in order.</summary>
internal sealed class FlatSource : ILandblockSource
{
    private readonly Func<uint, bool> _failFirst;
    private readonly Random _random = new(7);
    private readonly Dictionary<uint, int> _calls = [];
    private readonly List<uint> _order = [];
    private readonly object _gate = new();

    public FlatSource(Func<uint, bool>? failFirst = null) => _failFirst = failFirst ?? (_ => false);

    public bool Jitter { get; init; }

    /// <summary>Called at the start of each load, on the loader thread.</summary>
    public Action<uint>? OnLoad { get; init; }

    /// <summary>Each load sleeps this long first.</summary>
    public int DelayMilliseconds { get; init; }

    /// <summary>Every landblock loaded so far, in the order the loads started.</summary>
    public IReadOnlyList<uint> Loads()
    {
        lock (_gate)
        {
            return [.. _order];
        }
    }

    public int Calls(uint landblockId)
    {
        lock (_gate)
        {
            return _calls.GetValueOrDefault(landblockId);
        }
    }

    public LoadedLandblock Load(uint landblockId)
    {
        int call;
        lock (_gate)
        {
            call = _calls[landblockId] = _calls.GetValueOrDefault(landblockId) + 1;
            _order.Add(landblockId);
        }

        OnLoad?.Invoke(landblockId);
        if (DelayMilliseconds > 0)
        {
            Thread.Sleep(DelayMilliseconds);
        }

        if (Jitter)
        {
            Thread.SpinWait(_random.Next(0, 2000)); // vary how the loader interleaves with the frame loop
        }

        if (call == 1 && _failFirst(landblockId))
        {
            throw new IOException($"simulated read error for 0x{landblockId:X8}");
        }

        return new LoadedLandblock(new LandBlock { Id = landblockId, Height = Enumerable.Repeat((byte)10, 81).ToArray() }, [], new Dictionary<uint, Environment>());
    }
}
