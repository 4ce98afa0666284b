using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.App.Movement;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Xunit.Abstractions;

namespace AcDream.App.Tests;

/// <summary>
/// A player under gravity (<see cref="PlayerMovementMode"/> with <see cref="MovementOptions.Player"/>, frames of 1/30 s,
/// and of 0.1 s, its longest step, at a walk and a run; each from six starts a sixth of a frame's move apart) runs down each Holtburg cellar stair into its cellar and back up into the room above, at a walk
/// (2 m/s), a run (4 m/s) and the game's fastest speed (50 m/s: 1.67 m a frame), in lanes across the stair, in
/// both world frames: every leg reaches its end, never refused for good nor stuck in the stair.
/// </summary>
public class StairRunTests(ITestOutputHelper output)
{
    private const uint Holtburg = 0xA9B4FFFFu;

    private static PhysicsEngine Engine(bool global)
    {
        PhysicsEngine engine = global ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        Dictionary<uint, GfxObj> gfxObjs = HoltburgFixtures.ReadObjects();
        var cells = new List<EnvCell>();
        foreach ((uint cellId, GfxObj stair, Stab placement) in ObjectPlacements.CellarStairs())
        {
            gfxObjs[stair.Id] = stair;
            cells.Add(new EnvCell { Id = cellId, StaticObjects = [placement] });
        }

        var surfaces = HoltburgFixtures.ReadAll().Select(c => new CellSurface(c.CellId, c.EnvCell, c.CellStruct)).ToList();
        List<ObjectSurface> objects = ObjectSurface.FromLandblock(Holtburg, ObjectPlacements.HoltburgInfo(), cells, gfxObjs, new Dictionary<uint, Setup>());
        var flat = new TerrainSurface(Enumerable.Repeat((byte)47, 81).ToArray(), Enumerable.Range(0, 256).Select(i => 2f * i).ToArray(), Holtburg);
        engine.AddLandblock(Holtburg, flat, surfaces, objects);
        engine.AddLandblock(0xA9B3FFFFu, new TerrainSurface(Enumerable.Repeat((byte)47, 81).ToArray(), Enumerable.Range(0, 256).Select(i => 2f * i).ToArray(), 0xA9B3FFFFu), []);
        return engine;
    }

    /// <summary>One leg: face a heading (0 north, π/2 east) and run until the position passes a line, within a time limit.</summary>
    private sealed record Leg(float Heading, Func<Vector3, bool> Done, string Name);

    public static TheoryData<string, float, float, bool> Runs()
    {
        var data = new TheoryData<string, float, float, bool>();
        foreach (bool global in new[] { false, true })
        {
            foreach (float speed in new[] { PlayerMovementMode.WalkSpeed, PlayerMovementMode.RunSpeed, 50f })
            {
                foreach (float lane in new[] { 141.0f, 141.3f, 141.55f })
                {
                    data.Add("cottage", lane, speed, global);
                }

                foreach (float lane in new[] { 153.6f, 153.92f, 154.25f })
                {
                    data.Add("building B", lane, speed, global);
                }
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Runs))]
    public void The_player_runs_down_into_the_cellar_and_back_up_at_any_speed(string cellar, float lane, float speed, bool global)
    {
        PhysicsEngine engine = Engine(global);
        foreach (float frame in speed > PlayerMovementMode.RunSpeed ? [1f / 30f] : new[] { 1f / 30f, new CharacterSettings().MaxStepSeconds })
        {
            for (int phase = 0; phase < 6; phase++)
            {
                // Six starts, a sixth of a frame's move apart, so the frames meet each tread's edge at six phases.
                Run(engine, cellar, lane, speed, global, frame, phase * speed * frame / 6f);
            }
        }
    }

    private void Run(PhysicsEngine engine, string cellar, float lane, float speed, bool global, float frame, float offset)
    {
        bool cottage = cellar == "cottage";
        uint room = cottage ? 0xA9B40143u : 0xA9B40171u, cellarId = cottage ? ObjectPlacements.CottageCellar : ObjectPlacements.BuildingBCellar;

        // Cottage: from the room west of the opening east to the lane at the ramp's top (y 6.2), north down the
        // ramp (it falls to the north) into the cellar, back south up it, and west into the room. Building B: from
        // the room north of its opening south down the landing, ramp and tread into the cellar, and back north.
        (Vector3 start, Leg[] legs) = cottage
            ? (new Vector3(139.2f - offset, 6.2f, 94f), new Leg[]
            {
                new(MathF.PI / 2f, p => p.X >= lane, "east to the ramp's top"),
                new(0f, p => p.Y >= 9.6f, "north down into the cellar"),
                new(MathF.PI, p => p.Y <= 6.2f, "south up the ramp"),
                new(-MathF.PI / 2f, p => p.X <= 139.4f, "west into the room"),
            })
            : (new Vector3(lane, 12.5f + offset, 94f), new Leg[]
            {
                new(MathF.PI, p => p.Y <= 5.2f, "south down into the cellar"),
                new(0f, p => p.Y >= 11.5f, "north up into the room"),
            });

        var mode = new PlayerMovementMode(engine, engine.ToWorld(Holtburg, start), room, 0f, MovementOptions.Player) { RunMetresPerSecond = speed };
        var cells = new List<uint> { room };
        int frames = 0;
        foreach (Leg leg in legs)
        {
            mode.Heading = leg.Heading;
            int legFrames = 0;
            var last = new List<string>();
            while (!leg.Done(engine.ToLandblockLocal(Holtburg, mode.Position)))
            {
                CharacterStep f = mode.Update(new MovementIntent(1f, 0f, 0f, Run: speed != PlayerMovementMode.WalkSpeed), frame);
                Vector3 local = engine.ToLandblockLocal(Holtburg, mode.Position);
                last.Add($"frame {legFrames}: ({local.X:F4}, {local.Y:F4}, {local.Z:F4}) 0x{mode.CellId:X8} ground {mode.IsOnGround} {f}");
                if (last.Count > 12)
                {
                    last.RemoveAt(0);
                }

                if (mode.CellId != cells[^1])
                {
                    cells.Add(mode.CellId);
                }

                legFrames++;
                frames++;
                legFrames.Should().BeLessThan((int)(20f / frame), $"{cellar}, lane {lane}, {speed} m/s, frames of {frame:F3} s, start {offset:F3} m back, {(global ? "global" : "centred")}: '{leg.Name}' never ends (20 s):\n{string.Join("\n", last)}");
            }
        }

        string path = string.Join(" → ", cells.Select(c => $"0x{c:X8}")) + $"; ends at {engine.ToLandblockLocal(Holtburg, mode.Position)}";
        output.WriteLine($"{cellar}, lane {lane}, {speed} m/s, start {offset:F3} m back: {frames} frames, {path}");
        cells.Should().Contain(cellarId, $"the run went down into the cellar: {path}");
        mode.CellId.Should().Be(room, $"back in the room: {path}");
        engine.ToLandblockLocal(Holtburg, mode.Position).Z.Should().BeApproximately(94f, 1e-3f, "on the room's floor");
    }
}
