using System.Numerics;
using AcDream.Core.Physics;
using BenchmarkDotNet.Attributes;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// What seeing a move costs when asked for: the player's moves on the floors of the 22 real Holtburg cells (as
/// <see cref="ResolveIndoorBenchmarks"/>) through the general <c>Resolve</c> (<see cref="Request"/>), the same moves drawn
/// (<see cref="Drawn"/>: <c>DrawMove</c> into a sink that counts what it is handed) and the same moves with a recorder
/// set that keeps nothing (<see cref="Recorded"/>). Compare them side by side:
/// <c>--compare 'SeeingBenchmarks.Request::SeeingBenchmarks.Drawn'</c>.
/// </summary>
[MemoryDiagnoser]
public class SeeingBenchmarks
{
    private const int Moves = 1024;

    private readonly MoveRequest[] _requests = new MoveRequest[Moves];
    private readonly Counter _sink = new();
    private PhysicsEngine _engine = null!, _recorded = null!;

    [GlobalSetup]
    public void Setup()
    {
        var random = new Random(5);
        var fixtures = World.HoltburgFixtures();
        List<CellSurface> surfaces = World.Surfaces(fixtures);
        _engine = World.IndoorEngine(surfaces);
        _recorded = World.IndoorEngine(surfaces);
        _recorded.Recorder = new Nothing();
        List<World.WallFace> walls = World.Walls(fixtures);
        int redrawn = 0;
        for (int i = 0; i < Moves; i++)
        {
            (Vector3 position, uint cellId) = World.IndoorStart(random, fixtures, surfaces, walls, ref redrawn);
            _requests[i] = new MoveRequest(position, cellId, World.RandomDelta(random, 0.1f, 0.3f), World.PlayerStepUp) { Options = MovementOptions.Player };
        }
    }

    /// <summary>The general call, no drawing, no recorder.</summary>
    [Benchmark(Baseline = true, OperationsPerInvoke = Moves)]
    public float Request()
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += _engine.Resolve(in _requests[i]).Answer.Position.X;
        }

        return sum;
    }

    /// <summary>The same moves drawn into a sink that counts lines and triangles.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Drawn()
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += _engine.DrawMove(in _requests[i], _sink).Answer.Position.X;
        }

        return sum + _sink.Count;
    }

    /// <summary>The same moves on an engine whose recorder is handed each call and keeps nothing.</summary>
    [Benchmark(OperationsPerInvoke = Moves)]
    public float Recorded()
    {
        float sum = 0f;
        for (int i = 0; i < Moves; i++)
        {
            sum += _recorded.Resolve(in _requests[i]).Answer.Position.X;
        }

        return sum;
    }

    private sealed class Counter : IDebugSink
    {
        public int Count;

        public void Line(Vector3 a, Vector3 b, DrawKind kind, uint id) => Count++;

        public void Triangle(Vector3 a, Vector3 b, Vector3 c, DrawKind kind, uint id) => Count++;
    }

    private sealed class Nothing : IEngineRecorder
    {
        public void LandblockAdded(uint landblockId) { }

        public void LandblockRemoved(uint landblockId) { }

        public void MoverAdded(uint id, MoverShape shape, Vector3 position, uint cellId, Quaternion orientation, MoverState state) { }

        public void MoverMoved(uint id, Vector3 position, uint cellId, Quaternion orientation) { }

        public void MoverStateSet(uint id, MoverState state) { }

        public void DoorOpened(uint doorId) { }

        public void DoorClosed(uint doorId) { }

        public void MoverRemoved(uint id, bool removed) { }

        public void MoversOfLandblockRemoved(uint landblockId, int removed) { }

        public void Committed(long commitNumber) { }

        public void Resolved(in MoveRequest request, ReadOnlySpan<uint> touched, in MoveResult result) { }

        public void Cast(in CastRequest request, in CastHit hit) { }
    }
}
