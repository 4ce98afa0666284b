using System.Diagnostics;
using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// Issue 29, defect 1: every loop of a call ends for any finite input. A swept move through the air whose sub-steps were
/// capped at <see cref="PhysicsConstants.MaxSweepSteps"/> cut each of them into up to as many sub-steps again: a player's
/// call with a delta of 1e30 m took 65,536² sub-steps and gave no answer after 20 s.
/// </summary>
public class BoundedLoopTests
{
    private const uint Lb = 0x1010FFFFu;
    private const uint LoadedCell = 0x10100001u;

    public static TheoryData<float, float, float, uint> Starts() => new()
    {
        { 1e6f, 1e6f, 0f, 0u },
        { 1e30f, 0f, 0f, 0u },
        { -1e30f, -1e30f, 1e30f, 0u },
        { float.MaxValue, float.MaxValue, float.MaxValue, 0u },
        { 1e6f, 1e6f, 0f, LoadedCell },
        { 1e30f, 0f, 0f, LoadedCell },
        { (16 * 192) + 50, (16 * 192) + 50, 0f, LoadedCell }, // in the loaded landblock: off the world ahead
    };

    [Theory]
    [MemberData(nameof(Starts))]
    public async Task Resolve_HugeDeltaSweptThroughTheAir_AnswersInBoundedTime(float x, float y, float z, uint cellId)
    {
        var engine = new PhysicsEngine();
        engine.AddLandblock(Lb, FlatTerrain(0f, Lb), []);
        var start = new Vector3(x, y, z);
        var delta = new Vector3(1e30f, -1e30f, 1e30f);
        var bodyOnly = new MovementOptions { SweepStepLength = 0.48f, Body = MoverBody.Player };
        foreach (MovementOptions options in new[] { MovementOptions.Player, bodyOnly, bodyOnly with { Vertical = true } })
        {
            // On a worker thread with a time limit: a regression fails here instead of hanging the suite.
            var clock = Stopwatch.StartNew();
            Task<ResolveResult> call = Task.Factory.StartNew(() => engine.Resolve(start, cellId, delta, 0.5f, options), TaskCreationOptions.LongRunning);
            (await Task.WhenAny(call, Task.Delay(TimeSpan.FromSeconds(8)))).Should().BeSameAs(call, $"a move of {delta} from {start} in 0x{cellId:X8} must end; still running after 8 s");
            ResolveResult r = await call;
            string what = $"{start} in 0x{cellId:X8} by {delta} ({clock.ElapsedMilliseconds} ms) → {r}";
            (float.IsFinite(r.Position.X) && float.IsFinite(r.Position.Y) && float.IsFinite(r.Position.Z)).Should().BeTrue(what);
            (r.Position.X, r.Position.Y).Should().Be((start.X, start.Y), $"off the world or into land not loaded, the mover keeps its place: {what}");
            r.Outcome.Should().BeOneOf([ResolveOutcome.Held, ResolveOutcome.EdgeOfWorld, ResolveOutcome.UnloadedAhead, ResolveOutcome.Moved], what);
        }
    }
}
