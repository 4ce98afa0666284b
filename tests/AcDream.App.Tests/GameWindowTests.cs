using System.Numerics;
using AcDream.App.Movement;
using AcDream.App.Streaming;
using AcDream.App.World;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Environment = AcDream.Core.Dat.Environment;

namespace AcDream.App.Tests;

public class GameWindowTests
{
    private const uint Holtburg = HoltburgWorld.Holtburg;
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(20);

    // An outdoor mover just west of the cottage's west door 0x0145 (outdoor portal at x = 136.3), stepping 1 m east onto its floor.
    private static readonly Vector3 OutsideDoor = new(135.5f, 5.15f, 94f);
    private static readonly Vector3 IntoDoor = new(1f, 0f, 0f);

    [Fact]
    public void ApplyLoadedTerrain_HoltburgLandblock_RegistersTerrainAndCells()
    {
        var world = new HoltburgWorld();
        using var window = new GameWindow(world, world.HeightTable, Holtburg);

        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out string? error).Should().BeTrue($"error: {error}");

        window.Physics.ContainsLandblock(Holtburg).Should().BeTrue();
        ResolveResult door = window.Physics.Resolve(OutsideDoor, 0xA9B40001u, IntoDoor, 0.5f);
        door.CellId.Should().Be(0xA9B40145u, $"a step through the west door lands in it, got 0x{door.CellId:X8} at {door.Position}");
        Vector3.Distance(door.Position, new Vector3(136.5f, 5.15f, 94f)).Should().BeLessThan(1e-4f, $"on the door's floor at 94 m, got {door.Position}");
        door.IsOnGround.Should().BeTrue();

        ResolveResult room = window.Physics.Resolve(new Vector3(139f, 10f, 94f), 0xA9B40143u, new Vector3(0f, 0.1f, 0f), 0.5f);
        room.CellId.Should().Be(0xA9B40143u);
        room.IsOnGround.Should().BeTrue();
        room.Position.Y.Should().BeApproximately(10.1f, 1e-4f);
        room.Position.Z.Should().BeApproximately(94f, 1e-4f, "the main room's floor is at 94 m");

        float hill = world.Terrain(Holtburg).SampleZ(60f, 100f);
        window.Physics.Resolve(new Vector3(60f, 100f, 0f), 0xA9B40001u, Vector3.Zero, 0.5f).Position.Z
            .Should().Be(hill, "the streamed terrain is the world's terrain");
    }

    [Fact]
    public void UnloadLandblock_AfterApply_ResolveNoLongerFindsTerrainOrCells()
    {
        var world = new HoltburgWorld();
        using var window = new GameWindow(world, world.HeightTable, Holtburg);
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out _).Should().BeTrue();

        window.UnloadLandblockLocked(Holtburg);

        window.Physics.ContainsLandblock(Holtburg).Should().BeFalse();
        window.Physics.LandblockCount.Should().Be(0);
        ResolveResult door = window.Physics.Resolve(OutsideDoor, 0xA9B40001u, IntoDoor, 0.5f);
        door.Position.Should().Be(OutsideDoor, "with the landblock gone the mover is held where it is");
        (door.CellId & 0xFFFF).Should().BeLessThan(0x0100u, $"no cell is found any more, got 0x{door.CellId:X8}");
        ResolveResult room = window.Physics.Resolve(new Vector3(139f, 10f, 94f), 0xA9B40143u, new Vector3(0f, 0.1f, 0f), 0.5f);
        room.Position.Should().Be(new Vector3(139f, 10f, 94f), "an indoor mover of an unloaded landblock is held too");
    }

    [Fact]
    public void ApplyLoadedTerrain_Reload_GivesTheSameAnswersAsTheFirstLoad()
    {
        var world = new HoltburgWorld();
        using var window = new GameWindow(world, world.HeightTable, Holtburg);
        var random = new Random(11);
        var queries = Enumerable.Range(0, 200)
            .Select(_ => (Pos: new Vector3(120f + (random.NextSingle() * 50f), random.NextSingle() * 25f, 94f), Delta: new Vector3((random.NextSingle() - 0.5f) * 2f, (random.NextSingle() - 0.5f) * 2f, 0f)))
            .ToList();

        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out _).Should().BeTrue();
        var first = queries.Select(q => window.Physics.Resolve(q.Pos, 0xA9B40001u, q.Delta, 0.5f)).ToList();
        window.UnloadLandblockLocked(Holtburg);
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out _).Should().BeTrue();
        var second = queries.Select(q => window.Physics.Resolve(q.Pos, 0xA9B40001u, q.Delta, 0.5f)).ToList();

        second.Should().Equal(first, "a reloaded landblock resolves exactly as the first load did");
        first.Count(r => (r.CellId & 0xFFFF) >= 0x0100).Should().BeGreaterThan(0, "some queries land indoors, so the cells are compared too");
    }

    [Fact]
    public void ApplyLoadedTerrain_CellWithMissingEnvironmentOrBadGeometry_SkipsOnlyThatCellWithWarning()
    {
        var world = new HoltburgWorld();
        var warnings = new List<string>();
        using var window = new GameWindow(world, world.HeightTable, Holtburg, warnings.Add);
        LoadedLandblock real = world.Load(Holtburg);
        var environments = real.Environments.Where(e => e.Key != 0x0D000145u).ToDictionary(e => e.Key, e => e.Value);
        var broken = new CellStruct();
        broken.VertexArray.Vertices.Add(0, new SWVertex());
        broken.VertexArray.Vertices.Add(1, new SWVertex { Origin = Vector3.UnitX });
        broken.PhysicsPolygons.Add(0, new Polygon { VertexIds = [0, 1] }); // two vertices: not a polygon
        environments.Add(0x0D000180u, new Environment { Id = 0x0D000180u, Cells = { [0] = broken } });
        var cells = real.EnvCells.Append(new EnvCell { Id = 0xA9B40180u, EnvironmentId = 0x0180, Position = new Frame() }).ToList();

        window.ApplyLoadedTerrainLocked(Holtburg, new LoadedLandblock(real.LandBlock, cells, environments), out string? error).Should().BeTrue($"error: {error}");

        warnings.Should().HaveCount(2, string.Join(" | ", warnings));
        warnings.Should().Contain(w => w.Contains("0xA9B40145") && w.Contains("environment 0x0D000145 is missing"), string.Join(" | ", warnings));
        warnings.Should().Contain(w => w.Contains("0xA9B40180") && w.Contains("polygon"), string.Join(" | ", warnings));
        ResolveResult door = window.Physics.Resolve(OutsideDoor, 0xA9B40001u, IntoDoor, 0.5f);
        (door.CellId & 0xFFFF).Should().BeLessThan(0x0100u, $"the skipped door cell is not entered, got 0x{door.CellId:X8}");
        window.Physics.Resolve(new Vector3(139f, 10f, 94f), 0xA9B40143u, Vector3.Zero, 0.5f).CellId
            .Should().Be(0xA9B40143u, "the rest of the landblock loaded");
    }

    [Fact]
    public void ApplyLoadedTerrain_BadHeights_RegistersNothingAndSaysWhy()
    {
        var world = new HoltburgWorld();
        using var window = new GameWindow(world, world.HeightTable, Holtburg);
        LoadedLandblock real = world.Load(Holtburg);
        var bad = new LoadedLandblock(new LandBlock { Id = Holtburg, Height = new byte[80] }, real.EnvCells, real.Environments);

        window.ApplyLoadedTerrainLocked(Holtburg, bad, out string? error).Should().BeFalse();

        error.Should().Contain("81").And.Contain("80");
        window.Physics.LandblockCount.Should().Be(0, "never half a landblock");
        window.LoadedLandblocks.Should().BeEmpty();
    }

    [Fact]
    public void UpdateStreaming_LandblockFailsToLoad_ReportsItAndRetriesAfterTheDelay()
    {
        const uint failing = 0xA9B5FFFFu;
        var source = new FlatSource(id => id == failing);
        var log = new List<string>();
        using var window = new GameWindow(source, TestWorlds.LinearTable(), Holtburg, log.Add);
        var observer = new Vector3(96f, 96f, 0f);

        window.UpdateStreaming(observer);
        window.WaitForLoads(Patience).Should().BeTrue();
        window.UpdateStreaming(observer);

        log.Should().ContainSingle(l => l.Contains("0xA9B5FFFF") && l.Contains("simulated read error"), string.Join(" | ", log));
        window.Physics.ContainsLandblock(failing).Should().BeFalse();
        window.Physics.LandblockCount.Should().Be(8, "the other eight landblocks of the window loaded");
        for (int frame = 0; frame < GameWindow.RetryDelayFrames - 2; frame++)
        {
            window.UpdateStreaming(observer);
            window.WaitForLoads(Patience).Should().BeTrue();
        }

        source.Calls(failing).Should().Be(1, "no retry before the delay");
        for (int frame = 0; frame < 4; frame++)
        {
            window.UpdateStreaming(observer);
            window.WaitForLoads(Patience).Should().BeTrue();
        }

        source.Calls(failing).Should().Be(2, "retried once after the delay");
        window.Physics.ContainsLandblock(failing).Should().BeTrue("the retry succeeded");
        window.Physics.LandblockCount.Should().Be(9);
    }

    [Theory]
    [InlineData(60f, 100f, 94f, 0xA9B40001u)] // outdoors on a hill
    [InlineData(139f, 10f, 94f, 0xA9B40143u)] // indoors, the cottage's main room
    public void PlayerMovementMode_LandblockUnloadedAndReloaded_KeepsAValidPosition(float x, float y, float z, uint cellId)
    {
        var world = new HoltburgWorld();
        using var window = new GameWindow(world, world.HeightTable, Holtburg);
        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out _).Should().BeTrue();
        var mode = new PlayerMovementMode(window.Physics, new Vector3(x, y, z), cellId, 0f);
        mode.Update(default, 1f / 30f);
        Vector3 standing = mode.Position;
        uint cell = mode.CellId;

        window.UnloadLandblockLocked(Holtburg);
        var walk = new MovementIntent(1f, 0f, 0f, false);
        for (int i = 0; i < 30; i++)
        {
            mode.Update(walk, 1f / 30f);
            mode.Position.Should().Be(standing, $"frame {i}: held in place while the land is unloaded");
            mode.IsOnGround.Should().BeTrue($"frame {i}: held, not falling");
        }

        window.ApplyLoadedTerrainLocked(Holtburg, world.Load(Holtburg), out _).Should().BeTrue();
        mode.Update(default, 1f / 30f);
        mode.Position.Should().Be(standing, "after the reload the mover stands where it stood");
        mode.CellId.Should().Be(cell);
        mode.Update(walk, 1f / 30f);
        mode.Position.Y.Should().BeApproximately(standing.Y + (PlayerMovementMode.WalkSpeed / 30f), 1e-4f, "and walks on");
        float.IsFinite(mode.Position.Z).Should().BeTrue();
        mode.IsOnGround.Should().BeTrue();
    }

    [Fact]
    public void UpdateStreaming_TenThousandFramesWhileTheLoaderStreams_NoLandblockLostOrDoubled()
    {
        var source = new FlatSource(id => ((id >> 16) % 7) == 3) { Jitter = true }; // some landblocks fail once
        using var window = new GameWindow(source, TestWorlds.LinearTable(), Holtburg);
        var registered = new HashSet<uint>();
        int doubled = 0, lost = 0;
        window.LandblockLoaded += id => doubled += registered.Add(id) ? 0 : 1;
        window.LandblockUnloaded += id => lost += registered.Remove(id) ? 0 : 1;
        PhysicsEngine engine = window.Physics;
        var mode = new PlayerMovementMode(engine, new Vector3(96f, 96f, 10f), 0xA9B40001u, 0f);

        for (int frame = 0; frame < 10_000; frame++)
        {
            // The observer circles 300 m around Holtburg, crossing a seam every few hundred frames.
            float angle = frame * MathF.Tau / 5000f;
            var observer = new Vector3(96f + (300f * MathF.Cos(angle)), 96f + (300f * MathF.Sin(angle)), 10f);
            window.UpdateStreaming(observer);
            mode.Update(new MovementIntent(1f, 0f, 0.3f, true), 1f / 30f);
            ResolveResult r = engine.Resolve(observer with { Z = 0f }, 0, new Vector3(0.5f, 0.5f, 0f), 0.5f);
            float.IsFinite(r.Position.X + r.Position.Y + r.Position.Z).Should().BeTrue($"frame {frame}: {r.Position}");
            bool here = engine.ContainsLandblock(window.LandblockAt(observer));
            bool there = engine.ContainsLandblock(window.LandblockAt(observer + new Vector3(0.5f, 0.5f, 0f)));
            // On the flat land (10 m) when it is loaded: moved there, or refused (unloaded land ahead) and
            // lifted onto the ground under it, as a mover below its ground always is. Held at Z 0 when not.
            r.Position.Z.Should().Be(here ? 10f : 0f, $"frame {frame}: on the flat land (10 m) when it is loaded (ahead: {there}), held at Z 0 when not; {r}");
            r.IsOnGround.Should().BeTrue($"frame {frame}: on the ground or held; {r}");
            engine.LandblockCount.Should().Be(window.LoadedLandblocks.Count, $"frame {frame}: the engine holds what the window loaded");
        }

        for (int settle = 0; settle < 3 * GameWindow.RetryDelayFrames && !window.LoadedLandblocks.ToHashSet().SetEquals(window.WindowLandblocks); settle++)
        {
            window.WaitForLoads(Patience).Should().BeTrue();
            window.UpdateStreaming(new Vector3(396f, 96f, 10f));
        }

        doubled.Should().Be(0, "no landblock registered twice");
        lost.Should().Be(0, "no unload of a landblock that was not registered");
        window.LoadedLandblocks.Should().BeEquivalentTo(window.WindowLandblocks, "at the end the engine holds exactly the window");
        window.WindowLandblocks.Should().HaveCount(9);
        engine.LandblockCount.Should().Be(9);
        window.WindowLandblocks.Should().OnlyContain(id => engine.ContainsLandblock(id));
        registered.Should().BeEquivalentTo(window.LoadedLandblocks);
    }

    [Theory]
    [InlineData(1e12f, 0f, 0xFEB4FFFFu)]
    [InlineData(-1e12f, 0f, 0x00B4FFFFu)]
    [InlineData(float.MaxValue, 0f, 0xFEB4FFFFu)]
    [InlineData(-float.MaxValue, 0f, 0x00B4FFFFu)]
    [InlineData(0f, 1e12f, 0xA9FEFFFFu)]
    [InlineData(0f, -1e12f, 0xA900FFFFu)]
    [InlineData(float.MaxValue, -float.MaxValue, 0xFE00FFFFu)]
    [InlineData(float.NegativeInfinity, float.PositiveInfinity, 0x00FEFFFFu)]
    [InlineData(16511.99f, 191.99f, 0xFEB4FFFFu)] // the east edge's last centimetre: (0xFE - 0xA9) × 192 + 191.99
    [InlineData(16512f, 0f, 0xFEB4FFFFu)] // one landblock past it
    [InlineData(-32448f, -34560f, 0x0000FFFFu)] // 0x00's west edge; 0x00's south edge
    [InlineData(-32448.02f, -34560.02f, 0x0000FFFFu)] // just past them
    [InlineData(-0.001f, 192f, 0xA8B5FFFFu)]
    public void LandblockAt_PositionsFarOffTheWorld_ClampToTheNearestEdge(float x, float y, uint expected)
    {
        using var window = new GameWindow(new FlatSource(), TestWorlds.LinearTable(), Holtburg);

        uint landblock = window.LandblockAt(new Vector3(x, y, 0f));

        landblock.Should().Be(expected, $"({x}, {y}) is in landblock 0x{expected:X8} or off the world beyond it; got 0x{landblock:X8}");
    }

    [Fact]
    public void LandblockAt_NaN_Throws()
    {
        using var window = new GameWindow(new FlatSource(), TestWorlds.LinearTable(), Holtburg);

        FluentActions.Invoking(() => window.LandblockAt(new Vector3(float.NaN, 0f, 0f))).Should().Throw<ArgumentException>().WithMessage("*NaN*");
    }

    [Fact]
    public void UpdateStreaming_TeleportEveryFrameWithSlowLoads_DropsStaleRequestsAndLoadsTheNearestFirst()
    {
        var source = new FlatSource { DelayMilliseconds = 10 };
        using var window = new GameWindow(source, TestWorlds.LinearTable(), Holtburg);
        static Vector3 Teleport(int frame) => new((((frame * 3) - 60) * 192f) + 96f, 96f, 0f); // 3 landblocks a frame: windows never overlap

        for (int frame = 0; frame < 40; frame++)
        {
            window.UpdateStreaming(Teleport(frame));
        }

        Vector3 destination = Teleport(40);
        int frames = 0;
        do
        {
            window.UpdateStreaming(destination);
            window.WaitForLoads(Patience).Should().BeTrue();
            frames++;
        }
        while (frames < 100 && !window.LoadedLandblocks.ToHashSet().SetEquals(window.WindowLandblocks));

        IReadOnlyList<uint> loads = source.Loads();
        uint centre = window.LandblockAt(destination);
        window.LoadedLandblocks.Should().HaveCount(9).And.BeEquivalentTo(window.WindowLandblocks, "the destination window is complete");
        loads.Count.Should().BeLessThanOrEqualTo(9 + 10, $"9 destination loads plus the few stale ones in flight, not one per stale request; {loads.Count} loads: {string.Join(" ", loads.Select(id => $"{id >> 16:X4}"))}");
        List<uint> atDestination = loads.Where(window.WindowLandblocks.Contains).ToList();
        atDestination.Should().OnlyHaveUniqueItems().And.HaveCount(9, $"each destination landblock loads once: {string.Join(" ", atDestination.Select(id => $"{id >> 16:X4}"))}");
        atDestination[0].Should().Be(centre, $"the observer's own landblock 0x{centre:X8} comes first; order {string.Join(" ", atDestination.Select(id => $"{id >> 16:X4}"))}");
        atDestination.Skip(1).Take(4).Select(id => Math.Abs((int)(id >> 24) - (int)(centre >> 24)) + Math.Abs((int)((id >> 16) & 0xFF) - (int)((centre >> 16) & 0xFF)))
            .Should().AllBeEquivalentTo(1, $"then its four edge neighbours, then the corners; order {string.Join(" ", atDestination.Select(id => $"{id >> 16:X4}"))}");
    }

    [Theory]
    [InlineData("LandblockLoaded", 9)] // disposed while registering the 9 loads: the rest still register
    [InlineData("LandblockUnloaded", 0)] // disposed while unloading Holtburg's window: nothing requested after
    [InlineData("log", 8)] // 0xAEB4 failed, the other 8 register
    [InlineData("source", 1)] // disposed while loading 0xAEB4 (nearest first): it finishes, the 8 queued are dropped
    public async Task Dispose_FromAHandlerTheLogOrTheSource_ReturnsAndTheWindowStaysUsable(string from, int registered)
    {
        GameWindow? window = null;
        int calls = 0; // callbacks that reached DisposeOnce; the first one disposes
        void DisposeOnce()
        {
            if (Interlocked.Increment(ref calls) == 1)
            {
                window!.Dispose();
            }
        }

        var observer = new Vector3(96f, 96f, 0f);
        var elsewhere = new Vector3(96f + (5 * 192f), 96f, 0f);
        var source = new FlatSource(id => from == "log" && id == 0xAEB4FFFFu) // the first load of 0xAEB4 fails: a log line
        {
            OnLoad = id => { if (from == "source" && id == 0xAEB4FFFFu) { DisposeOnce(); } },
        };
        window = new GameWindow(source, TestWorlds.LinearTable(), Holtburg, _ => { if (from == "log") { DisposeOnce(); } });
        window.LandblockLoaded += id => { if (from == "LandblockLoaded" && id == 0xAEB4FFFFu) { DisposeOnce(); } };
        window.LandblockUnloaded += _ => { if (from == "LandblockUnloaded") { DisposeOnce(); } };
        window.UpdateStreaming(observer);
        window.WaitForLoads(Patience).Should().BeTrue();
        window.UpdateStreaming(observer);
        window.LoadedLandblocks.Should().HaveCount(9);

        // On a worker thread with a time limit: a deadlock fails here instead of hanging the suite.
        Task frames = Task.Factory.StartNew(
            () =>
            {
                window.UpdateStreaming(elsewhere);
                window.WaitForLoads(Patience);
                window.UpdateStreaming(elsewhere);
                window.UpdateStreaming(elsewhere);
                window.WaitForLoads(Patience).Should().BeTrue("nothing is left in flight after Dispose");
            },
            TaskCreationOptions.LongRunning);
        (await Task.WhenAny(frames, Task.Delay(TimeSpan.FromSeconds(10)))).Should().BeSameAs(frames, $"Dispose from the {from} callback must not deadlock the frame; still running after 10 s");
        await frames;

        calls.Should().BePositive($"the {from} callback ran and disposed the window");
        window.Physics.LandblockCount.Should().Be(window.LoadedLandblocks.Count, "the engine holds what the window loaded");
        window.LoadedLandblocks.Should().HaveCount(registered, $"loaded: {string.Join(" ", window.LoadedLandblocks.Select(id => $"{id >> 16:X4}"))}");
        window.LoadedLandblocks.Except(window.WindowLandblocks).Should().BeEmpty("the frame still unloaded what it left behind");
        int loads = source.Loads().Count;
        window.UpdateStreaming(observer);
        Thread.Sleep(50);
        source.Loads().Count.Should().Be(loads, "a disposed window requests nothing more");
        window.Dispose(); // a second Dispose is harmless
    }
}
