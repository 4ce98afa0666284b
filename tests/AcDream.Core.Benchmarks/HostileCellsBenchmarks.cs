using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// Issue 8, defect 9: one Resolve in a hostile portal graph (five floorless shafts, 60 floor openings
/// each into the next: 60⁴ cell visits unbounded) against the same 0.1 m move in one plain room
/// (the baseline). The search is bounded by <see cref="PhysicsConstants.MaxCellVisits"/>.
/// </summary>
[MemoryDiagnoser]
public class HostileCellsBenchmarks
{
    private const uint Lb = 0xA9B4FFFFu;
    private static readonly Vector3 Start = new(50, 50, 100);
    private static readonly Vector3 Move = new(0.1f, 0, 0);
    private PhysicsEngine _room = null!;
    private PhysicsEngine _shafts = null!;

    [GlobalSetup]
    public void Setup()
    {
        var flat = new TerrainSurface(new byte[81], World.ConstantTable(0f), Lb);
        _room = new PhysicsEngine(Lb);
        _room.AddLandblock(Lb, flat, [new CellBuilder(0xA9B40100u, new Vector3(50, 50, 100)).Floor(-2, -2, 2, 2, 0).Build()]);

        var cells = new List<CellSurface>();
        for (int s = 0; s < 5; s++)
        {
            var b = new CellBuilder(0xA9B40100u + (uint)s, new Vector3(50, 50, 100 - (s * 0.1f)));
            for (int k = 0; k < 60; k++)
            {
                b.Portal((ushort)(0x0100 + (s + 1 < 5 ? s + 1 : s - 1)), new Vector3(0, 0, 1), CellBuilder.Square(-2, -2, 2, 2, 0));
            }

            cells.Add(b.Build());
        }

        _shafts = new PhysicsEngine(Lb);
        _shafts.AddLandblock(Lb, flat, cells);
    }

    [Benchmark(Baseline = true)]
    public ResolveResult PlainRoom() => _room.Resolve(Start, 0xA9B40100u, Move, 0.5f);

    [Benchmark]
    public ResolveResult HostileShafts() => _shafts.Resolve(Start, 0xA9B40100u, Move, 0.5f);
}
