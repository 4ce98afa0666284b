using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Moving;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The engine's recorder (<see cref="PhysicsEngine.Recorder"/>): it sees every call that changes the engine or asks it a
/// move or a cast, in order, with the answers the caller got; calls that throw and the spec's calls are not seen; every
/// answer is the same bits with and without one; without one a move and a cast allocate nothing.
/// </summary>
public class RecorderTests
{
    private const uint South = 0xA9B3FFFFu;
    private const uint MainRoom = 0xA9B40143;

    [Fact]
    [Trait("Mutation", "MoverRegistry")]
    public void A_recorder_sees_every_call_in_order_with_the_answers_the_caller_got()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        var log = new Log();
        engine.Recorder = log;
        engine.Recorder.Should().BeSameAs(log);
        Vector3 outside = engine.ToWorld(TestData.Holtburg, new Vector3(100f, 100f, 94f));

        engine.RemoveLandblock(0xA9B30000u);
        engine.AddLandblock(South, TestData.FlatTerrain(94f, South), []);
        engine.Movers.Add(20, MoverKit.Human, outside + new Vector3(1f, 0f, 0f), 0xA9B40001, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Add(30, MoverKit.Human, outside + new Vector3(0f, 5f, 0f), 0xA9B40001, Quaternion.Identity, MoverState.Door);
        engine.Movers.Commit();
        engine.Movers.Move(20, outside + new Vector3(0.6f, 0f, 0f), 0xA9B40001, Quaternion.Identity);
        engine.Movers.SetState(20, MoverState.Player);
        engine.Movers.Open(30);
        engine.Movers.Close(30);
        engine.Movers.Commit();
        Span<uint> touched = stackalloc uint[4];
        MoveResult moved = engine.Resolve(new MoveRequest(outside, 0, new Vector3(0.5f, 0f, 0f), 0.6f) { Options = MovementOptions.Player, MoverId = 7, WithReport = true }, touched);
        CastHit hit = engine.Cast(new CastRequest(outside + new Vector3(0f, 0f, 1f), 0, new Vector3(3f, 0f, 0f)) { Options = new CastOptions(0.2f) });
        bool removed = engine.Movers.Remove(20), again = engine.Movers.Remove(20);
        int ofLandblock = engine.Movers.RemoveLandblock(TestData.Holtburg);
        engine.Movers.Commit();

        // Not seen: a call that throws (it changed nothing), the spec's calls and the queries.
        FluentActions.Invoking(() => engine.Movers.Move(99, outside, 0xA9B40001, Quaternion.Identity)).Should().Throw<ArgumentException>();
        FluentActions.Invoking(() => engine.Resolve(new MoveRequest(new Vector3(float.NaN), 0, Vector3.Zero, 0.6f))).Should().Throw<ArgumentException>();
        _ = engine.Resolve(outside, 0, new Vector3(0.5f, 0f, 0f), 0.6f);
        _ = engine.Resolve(outside, 0, new Vector3(0.5f, 0f, 0f), 0.6f, MovementOptions.Player);
        _ = engine.TryGetGround(outside, 0, out _, out _);
        _ = engine.FindCell(outside, 0);

        moved.TouchedCount.Should().Be(1, "the move along X passes the creature moved in its way");
        log.Calls.Should().Equal(
            "landblock- 0xA9B30000",
            "landblock+ 0xA9B3FFFF",
            $"add 20 {Bits(outside + new Vector3(1f, 0f, 0f))} 0xA9B40001 Creature cylinder 0.48x1.835",
            $"add 30 {Bits(outside + new Vector3(0f, 5f, 0f))} 0xA9B40001 Door cylinder 0.48x1.835",
            "commit 1",
            $"move 20 {Bits(outside + new Vector3(0.6f, 0f, 0f))} 0xA9B40001",
            "state 20 Creature 0x8",
            "open 30",
            "close 30",
            "commit 2",
            $"resolve {Bits(outside)} mover 7 span 4 -> {Bits(moved)} touched {string.Join(",", touched[..moved.TouchedCount].ToArray())}",
            $"cast {Bits(outside + new Vector3(0f, 0f, 1f))} -> {Bits(hit)}",
            $"remove 20 {removed}",
            $"remove 20 {again}",
            $"remove movers of 0xA9B4FFFF {ofLandblock}",
            "commit 3");
        (removed, again, ofLandblock).Should().Be((true, false, 1));

        engine.Recorder = null;
        engine.Movers.Commit();
        engine.RemoveLandblock(South);
        log.Calls.Should().HaveCount(16, "nothing is seen once the recorder is taken off");
    }

    [Theory]
    [InlineData("global")]
    [InlineData("centred")]
    public void Every_answer_is_the_same_bits_with_and_without_a_recorder(string frame)
    {
        PhysicsEngine plain = RealObjects.HoltburgWithCellarStairs(frame), recorded = RealObjects.HoltburgWithCellarStairs(frame);
        var log = new Log();
        recorded.Recorder = log;
        var plainMoves = new List<string>();
        var recordedMoves = new List<string>();
        uint[] touched = new uint[8];
        foreach ((PhysicsEngine engine, List<string> answers) in new[] { (plain, plainMoves), (recorded, recordedMoves) })
        {
            Vector3 origin = engine.ToWorld(TestData.Holtburg, Vector3.Zero);
            engine.Movers.Add(20, MoverKit.Human, origin + new Vector3(120f, 6f, 94f), 0xA9B40031, Quaternion.Identity, MoverState.Creature);
            engine.Movers.Commit();
            var random = new Random(5);
            for (int i = 0; i < 300; i++)
            {
                bool inside = i % 3 == 0;
                Vector3 at = origin + (inside ? new Vector3(138.5f, 6f, 94f) : new Vector3(110f + (20f * random.NextSingle()), -10f + (25f * random.NextSingle()), 94f));
                var delta = new Vector3((random.NextSingle() - 0.5f) * 1.2f, (random.NextSingle() - 0.5f) * 1.2f, (random.NextSingle() - 0.5f) * 0.3f);
                MoveResult move = engine.Resolve(new MoveRequest(at, inside ? MainRoom : 0, delta, 0.6f) { Options = MovementOptions.Player, MoverId = 7, WithReport = i % 2 == 0 }, touched);
                CastHit cast = engine.Cast(new CastRequest(at + new Vector3(0f, 0f, 1f), inside ? MainRoom : 0, delta * 10f) { Options = new CastOptions(0.3f) });
                answers.Add($"{Bits(move)} {Bits(cast)}");
            }
        }

        recordedMoves.Should().Equal(plainMoves);
        log.Calls.Should().HaveCount(2 + 600, "the recorder saw the mover's add, its commit and every move and cast");
        log.Calls.Where(c => c.StartsWith("resolve", StringComparison.Ordinal)).Select(c => c[(c.IndexOf("-> ", StringComparison.Ordinal) + 3)..c.IndexOf(" touched", StringComparison.Ordinal)])
            .Should().Equal(recordedMoves.Select(a => a[..a.IndexOf(" C ", StringComparison.Ordinal)]), "it saw the answers the caller got");
    }

    [Fact]
    public void Without_a_recorder_a_move_and_a_cast_allocate_nothing()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        engine.Recorder.Should().BeNull("none by default");
        Vector3 origin = engine.ToWorld(TestData.Holtburg, Vector3.Zero);
        engine.Movers.Add(20, MoverKit.Human, origin + new Vector3(120.8f, 6f, 94f), 0xA9B40031, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        var request = new MoveRequest(origin + new Vector3(120f, 6f, 94f), 0, new Vector3(0.3f, 0f, 0f), 0.6f) { Options = MovementOptions.Player, MoverId = 7, WithReport = true };
        var cast = new CastRequest(origin + new Vector3(118f, 6f, 95f), 0, new Vector3(4f, 0f, 0f)) { Options = new CastOptions(0.3f) };
        Span<uint> touched = stackalloc uint[4];
        MoveResult first = engine.Resolve(in request, touched);
        CastHit hit = engine.Cast(in cast);
        first.TouchedCount.Should().Be(1, "the move meets the creature");
        hit.Kind.Should().Be(SurfaceKind.Mover, "the cast meets the creature");

        long allocated = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 1000; i++)
        {
            _ = engine.Resolve(in request, touched);
            _ = engine.Cast(in cast);
        }

        (GC.GetAllocatedBytesForCurrentThread() - allocated).Should().Be(0, "a call with no recorder pays one null check and allocates nothing");
    }

    private static string Bits(float value) => BitConverter.SingleToUInt32Bits(value).ToString("X8");

    private static string Bits(Vector3 v) => $"({Bits(v.X)} {Bits(v.Y)} {Bits(v.Z)})";

    private static string Bits(in MoveResult r) =>
        $"{Bits(r.Answer.Position)} {r.Answer.CellId:X8} {r.Answer.IsOnGround} {r.Answer.Outcome} {Bits(r.Answer.SurfaceNormal)} "
        + $"{r.Report.Floor.Kind} {r.Report.Floor.Id:X8} {Bits(r.Report.Floor.Normal)} {r.Report.Wall.Kind} {r.Report.Wall.Id:X8} {Bits(r.Report.Wall.Normal)} {r.TouchedCount} {r.Commit}";

    private static string Bits(in CastHit h) => $"C {h.Hit} {Bits(h.Fraction)} {Bits(h.Position)} {Bits(h.Point)} {Bits(h.Normal)} {h.Kind} {h.Id:X8} {h.CellId:X8}";

    /// <summary>A recorder that keeps one line per call.</summary>
    private sealed class Log : IEngineRecorder
    {
        public List<string> Calls { get; } = [];

        public void LandblockAdded(uint landblockId) => Calls.Add($"landblock+ 0x{landblockId:X8}");

        public void LandblockRemoved(uint landblockId) => Calls.Add($"landblock- 0x{landblockId:X8}");

        public void MoverAdded(uint id, MoverShape shape, Vector3 position, uint cellId, Quaternion orientation, MoverState state) =>
            Calls.Add($"add {id} {Bits(position)} 0x{cellId:X8} {state.Kind} cylinder {shape.CylinderBody?.Radius}x{shape.CylinderBody?.Height}");

        public void MoverMoved(uint id, Vector3 position, uint cellId, Quaternion orientation) => Calls.Add($"move {id} {Bits(position)} 0x{cellId:X8}");

        public void MoverStateSet(uint id, MoverState state) => Calls.Add($"state {id} {state.Kind} 0x{(uint)state.Description:X}");

        public void DoorOpened(uint doorId) => Calls.Add($"open {doorId}");

        public void DoorClosed(uint doorId) => Calls.Add($"close {doorId}");

        public void MoverRemoved(uint id, bool removed) => Calls.Add($"remove {id} {removed}");

        public void MoversOfLandblockRemoved(uint landblockId, int removed) => Calls.Add($"remove movers of 0x{landblockId:X8} {removed}");

        public void Committed(long commitNumber) => Calls.Add($"commit {commitNumber}");

        public void Resolved(in MoveRequest request, ReadOnlySpan<uint> touched, in MoveResult result) =>
            Calls.Add($"resolve {Bits(request.Position)} mover {request.MoverId} span {touched.Length} -> {Bits(result)} touched {string.Join(",", touched[..Math.Min(result.TouchedCount, touched.Length)].ToArray())}");

        public void Cast(in CastRequest request, in CastHit hit) => Calls.Add($"cast {Bits(request.From)} -> {Bits(hit)}");
    }
}
