using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.App.Movement;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.App.Tests.TestWorlds;

namespace AcDream.App.Tests;

/// <summary>
/// Issue 8's "no fall-through" invariant: a player under gravity, driven by 100,000 frames of random
/// intents, never ends a frame below the floor it stood on and never falls for longer than a real
/// drop takes; inside a closed room (in both world frames, rotated, far from the origin) and in the
/// real Holtburg cottage. Also defect 2's case: walking into a closed room's wall at 81.4°.
/// </summary>
public class NoFallThroughTests
{
    private const float Frame = 1f / 30f;

    /// <summary>A closed 10 × 10 room (walls, no portals) rotated 30°, floor at 10 m, in landblock 0xABB4, 420 m from 0xA9B4's origin.</summary>
    private static (PhysicsEngine Engine, Vector3 Centre) ClosedRoom(bool global)
    {
        const uint landblock = 0xABB4FFFFu;
        var engine = global ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        CellSurface room = new CellBuilder(0xABB40100u, new Vector3(36f, 50f, 10f), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 6f))
            .Floor(-5, -5, 5, 5, 0)
            .Physics(CellBuilder.Square(-5, -5, 5, 5, 3f).Reverse().ToArray()) // ceiling
            .Build();
        engine.AddLandblock(landblock, new TerrainSurface(Heights((_, _) => 0), LinearTable(), landblock), [room]);
        return (engine, engine.GetLandblockOrigin(landblock) + new Vector3(36f, 50f, 10f));
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Update_HundredThousandRandomFramesInAClosedRoom_NeverBelowTheFloorNeverFalling(bool global)
    {
        (PhysicsEngine engine, Vector3 centre) = ClosedRoom(global);
        var mode = new PlayerMovementMode(engine, centre, 0xABB40100u, 0f, MovementOptions.Player);
        var random = new Random(8);
        MovementIntent intent = default;
        for (int frame = 0; frame < 100_000; frame++)
        {
            if (frame % 20 == 0)
            {
                intent = new MovementIntent(Range(random), Range(random), Range(random), random.Next(2) == 0);
            }

            mode.Update(intent, Frame);
            string what = $"{(global ? "global" : "centred")} frame {frame}: {mode.Position} in 0x{mode.CellId:X8}";
            mode.CellId.Should().Be(0xABB40100u, what);
            mode.Position.Z.Should().Be(10f, $"{what}: on the floor");
            mode.IsOnGround.Should().BeTrue(what);
        }
    }

    [Theory]
    [InlineData(true)]
    [InlineData(false)]
    public void Update_WalkingIntoAClosedRoomsWallAt81Degrees_NeverFallsThrough(bool global)
    {
        (PhysicsEngine engine, Vector3 centre) = ClosedRoom(global);
        for (int offset = 0; offset < 1024; offset++)
        {
            var start = centre + new Vector3((offset / 1024f * 6f) - 3f, (offset % 7) * 0.3f, 0f);
            var mode = new PlayerMovementMode(engine, start, 0xABB40100u, 81.4f * MathF.PI / 180f, MovementOptions.Player);
            for (int frame = 0; frame < 150; frame++)
            {
                mode.Update(new MovementIntent(1f, 0f, 0f, frame % 2 == 0), Frame);
                mode.Position.Z.Should().Be(10f, $"{(global ? "global" : "centred")} offset {offset}, frame {frame}: {mode.Position}, on ground {mode.IsOnGround}");
            }
        }
    }

    [Fact]
    public void Update_HundredThousandRandomFramesInTheRealCottage_NeverBelowAFloorNeverFallingLong()
    {
        var engine = new PhysicsEngine(Holtburg);
        var cells = HoltburgFixtures.ReadAll().Select(c => new CellSurface(c.CellId, c.EnvCell, c.CellStruct)).ToList();
        engine.AddLandblock(Holtburg, new TerrainSurface(Heights((_, _) => 94), LinearTable(), Holtburg), cells);
        engine.AddLandblock(0xA9B3FFFFu, new TerrainSurface(Heights((_, _) => 94), LinearTable(), 0xA9B3FFFFu), []);
        var mode = new PlayerMovementMode(engine, new Vector3(139f, 10f, 94f), 0xA9B40143u, 0f, MovementOptions.Player);
        var random = new Random(9);
        MovementIntent intent = default;
        int falling = 0, longestFall = 0, airborneFrames = 0;
        for (int frame = 0; frame < 100_000; frame++)
        {
            if (frame % 20 == 0)
            {
                intent = new MovementIntent(Range(random), Range(random), Range(random), random.Next(2) == 0);
            }

            mode.Update(intent, Frame);
            string what = $"frame {frame}: {mode.Position} in 0x{mode.CellId:X8}, on ground {mode.IsOnGround}";
            mode.Position.Z.Should().BeGreaterThanOrEqualTo(90f, $"{what}: never below the cellar floor, the lowest of the cottage");
            falling = mode.IsOnGround ? 0 : falling + 1;
            airborneFrames += mode.IsOnGround ? 0 : 1;
            longestFall = Math.Max(longestFall, falling);

            // The deepest drop here is 94 → 90 m: √(2·4/9.8) = 0.9 s, 27 frames. Allow 1.5 s.
            falling.Should().BeLessThanOrEqualTo(45, $"{what}: falling for {falling} frames");
        }

        Console.WriteLine($"cottage: longest fall {longestFall} frames, {airborneFrames} airborne frames, end {mode.Position} in 0x{mode.CellId:X8}");
    }

    private static float Range(Random random) => (float)((random.NextDouble() * 2) - 1);
}
