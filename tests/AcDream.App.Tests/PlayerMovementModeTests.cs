using System.Numerics;
using AcDream.App.Movement;
using AcDream.App.World;
using AcDream.Core.Physics;
using static AcDream.App.Tests.TestWorlds;

namespace AcDream.App.Tests;

public class PlayerMovementModeTests
{
    private const float Frame = 1f / 30f;
    private static readonly MovementIntent Idle = default;

    private static PhysicsEngine Flat(byte index) => Engine(Heights((_, _) => index));

    /// <summary>Holtburg's landblock with its terrain and the 22 real cells, centred on it.</summary>
    private static PhysicsEngine HoltburgEngine()
    {
        var world = new HoltburgWorld();
        var engine = new PhysicsEngine(HoltburgWorld.Holtburg);
        engine.AddLandblock(HoltburgWorld.Holtburg, world.Terrain(HoltburgWorld.Holtburg), world.CellSurfaces);
        return engine;
    }

    [Theory]
    [InlineData(false, PlayerMovementMode.WalkSpeed)]
    [InlineData(true, PlayerMovementMode.RunSpeed)]
    public void Update_ForwardForOneSecondOnFlatGround_MovesItsSpeedAlongTheHeading(bool run, float speed)
    {
        var mode = new PlayerMovementMode(Flat(50), new Vector3(96f, 96f, 50f), 0xA9B40001u, 0f);

        for (int i = 0; i < 30; i++)
        {
            mode.Update(new MovementIntent(1f, 0f, 0f, run), Frame).RefusedSteps.Should().Be(0, $"frame {i}");
        }

        mode.Position.X.Should().BeApproximately(96f, 1e-4f, "heading 0 is north");
        mode.Position.Y.Should().BeApproximately(96f + speed, 1e-3f, $"one second at {speed} m/s");
        mode.Position.Z.Should().Be(50f);
        mode.CellId.Should().Be(0xA9B40025u, "outdoor cell (4, 4) of Holtburg");
    }

    [Fact]
    public void Update_StrafeRightFacingEastThenTurn_MovesSouthAndTurnsNinetyDegreesPerSecond()
    {
        var mode = new PlayerMovementMode(Flat(50), new Vector3(96f, 96f, 50f), 0xA9B40001u, MathF.PI / 2f);

        for (int i = 0; i < 30; i++)
        {
            mode.Update(new MovementIntent(0f, 1f, 0f, false), Frame);
        }

        mode.Position.X.Should().BeApproximately(96f, 1e-3f);
        mode.Position.Y.Should().BeApproximately(96f - PlayerMovementMode.WalkSpeed, 1e-3f, "right of east is south");
        for (int i = 0; i < 30; i++)
        {
            mode.Update(new MovementIntent(0f, 0f, 1f, false), Frame);
        }

        mode.Heading.Should().BeApproximately(MathF.PI, 1e-4f, "a second of turning right from east faces south");
        mode.Position.Y.Should().BeApproximately(96f - PlayerMovementMode.WalkSpeed, 1e-3f, "turning in place does not move");
    }

    [Fact]
    public void Update_SlopeRisingMoreThanTheStepPerStep_RefusedWhenRunningClimbedWhenWalking()
    {
        // Vertex columns 0–1 at 0 m, 2–8 at 120 m: between x = 24 and 48 the ground rises 120 m in 24 m.
        // Running (0.133 m a frame) that is 0.67 m a step, over the 0.6 m limit; walking, 0.33 m.
        PhysicsEngine engine = Engine(Heights((x, _) => x >= 2 ? 120 : 0));
        var runner = new PlayerMovementMode(engine, new Vector3(20f, 96f, 0f), 0xA9B40001u, MathF.PI / 2f);
        var walker = new PlayerMovementMode(engine, new Vector3(20f, 96f, 0f), 0xA9B40001u, MathF.PI / 2f);
        int refused = 0;
        CharacterStep last = default;

        for (int i = 0; i < 90; i++)
        {
            last = runner.Update(new MovementIntent(1f, 0f, 0f, true), Frame);
            refused += last.RefusedSteps;
            CharacterStep walked = walker.Update(new MovementIntent(1f, 0f, 0f, false), Frame);
            walked.RefusedSteps.Should().Be(0, $"frame {i}: walking climbs");
            walked.LastRefusal.Should().BeNull($"frame {i}: nothing refused");
        }

        runner.Position.X.Should().BeInRange(23.8f, 24f, "the runner stops at the foot of the slope");
        runner.Position.Z.Should().Be(0f);
        refused.Should().BeGreaterThan(50, "every later running step is refused");
        last.LastRefusal.Should().Be(ResolveOutcome.StepTooHigh, "the engine's reason: the rise per step is over 0.6 m (no walkable-slope effect)");
        Vector3 slope = Vector3.Normalize(new Vector3(-120f, 0f, 24f));
        last.LastRefusalNormal.X.Should().BeApproximately(slope.X, 1e-4f, $"the slope's normal, got {last.LastRefusalNormal}");
        last.LastRefusalNormal.Y.Should().BeApproximately(0f, 1e-4f, $"got {last.LastRefusalNormal}");
        last.LastRefusalNormal.Z.Should().BeApproximately(slope.Z, 1e-4f, $"got {last.LastRefusalNormal}");
        walker.Position.X.Should().BeApproximately(20f + (3f * PlayerMovementMode.WalkSpeed), 1e-3f);
        walker.Position.Z.Should().BeApproximately((walker.Position.X - 24f) * 120f / 24f, 1e-3f, "the walker is on the slope");
    }

    [Fact]
    public void Update_LongFrameAtTheSlope_IsSplitIntoStepsSoTheStepLimitStillHolds()
    {
        PhysicsEngine engine = Engine(Heights((x, _) => x >= 2 ? 100 : 0));
        var whole = new PlayerMovementMode(engine, new Vector3(23f, 96f, 0f), 0xA9B40001u, MathF.PI / 2f);
        var split = new PlayerMovementMode(engine, new Vector3(23f, 96f, 0f), 0xA9B40001u, MathF.PI / 2f);

        CharacterStep frame = whole.Update(new MovementIntent(1f, 0f, 0f, false), 1f);
        for (int i = 0; i < 10; i++)
        {
            split.Update(new MovementIntent(1f, 0f, 0f, false), 0.1f);
        }

        frame.Steps.Should().Be(10, "1 s in steps of at most 0.1 s");
        whole.Position.Should().Be(split.Position, "a long frame is exactly its steps");
        frame.RefusedSteps.Should().BeGreaterThan(0, "0.2 m steps rise 0.83 m on the slope: refused");
        whole.Position.X.Should().BeLessThan(24.2f, $"the long frame did not jump up the slope; at {whole.Position}");
        whole.Update(Idle, 0.25f).Steps.Should().Be(3, "0.25 s is three steps of 0.083 s");
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void Update_IndoorStepOfOneMetre_ReportsTheEngineDoorwayWallAndItsNormal(bool player)
    {
        PhysicsEngine engine = HoltburgEngine();
        // The cottage's main room 0x0143 (94 m) meets the raised passage 0x0142 (95 m) at y = 13.1:
        // the doorway's opening starts 1 m up, so walking north the mover meets the wall under it.
        // The literal point stops on the doorway's plane; the player's body its radius short of it.
        MovementOptions effects = player ? MovementOptions.Player : default;
        float stopY = player ? 13.1f - MoverBody.Player.Radius : 13.1f;
        var mode = new PlayerMovementMode(engine, new Vector3(139f, 12.5f, 94f), 0xA9B40143u, 0f, effects);
        var walk = new MovementIntent(1f, 0f, 0f, false);

        int refused = 0;
        CharacterStep last = default;
        for (int i = 0; i < 30; i++)
        {
            last = mode.Update(walk, Frame);
            refused += last.RefusedSteps;
        }

        mode.CellId.Should().Be(0xA9B40143u);
        mode.Position.Z.Should().Be(94f);
        mode.Position.Y.Should().BeApproximately(stopY, 1e-3f, player ? "the body stopped its radius short of the wall" : "stopped at the doorway's plane");
        mode.Position.Y.Should().BeLessThanOrEqualTo(stopY, "never closer to the wall than that");
        refused.Should().BeGreaterThan(20);
        last.LastRefusal.Should().Be(ResolveOutcome.Wall, $"the engine's reason; frame {last}");
        last.LastRefusalNormal.X.Should().BeApproximately(0f, 1e-5f, $"the doorway wall faces south, towards the mover: {last.LastRefusalNormal}");
        last.LastRefusalNormal.Y.Should().BeApproximately(-1f, 1e-5f, $"{last.LastRefusalNormal}");
        last.LastRefusalNormal.Z.Should().BeApproximately(0f, 1e-5f, $"{last.LastRefusalNormal}");

        // Exactly what the engine answers for the same step.
        ResolveResult engineSays = engine.Resolve(mode.Position, mode.CellId, new Vector3(0f, PlayerMovementMode.WalkSpeed * Frame, 0f), PlayerMovementMode.StepUpHeight, effects);
        engineSays.IsRefused.Should().BeTrue($"{engineSays}");
        last.LastRefusal.Should().Be(engineSays.Outcome);
        last.LastRefusalNormal.Should().Be(engineSays.SurfaceNormal);
    }

    [Fact]
    public void Update_PointIntoTheMainRoomsEastWall_ReportsAWallWithNoSurfaceNormal()
    {
        // A point mover (the player's effects without the body): no floor and no doorway east of
        // x = 142.1 in 0x0143 is a floor edge, whose refusal names no surface.
        var mode = new PlayerMovementMode(HoltburgEngine(), new Vector3(139f, 10f, 94f), 0xA9B40143u, MathF.PI / 2f, MovementOptions.Player with { Body = null });

        CharacterStep last = default;
        int refused = 0;
        for (int i = 0; i < 90; i++)
        {
            last = mode.Update(new MovementIntent(1f, 0f, 0f, false), Frame);
            refused += last.RefusedSteps;
        }

        mode.Position.X.Should().BeInRange(141.9f, 142.1f, "stopped at the east wall");
        refused.Should().BeGreaterThan(30, "walking 6 m (90 frames) towards a wall 3.1 m (47 frames) away");
        last.LastRefusal.Should().Be(ResolveOutcome.Wall);
        last.LastRefusalNormal.Should().Be(Vector3.Zero, "the engine names no surface at a floor edge");
    }

    [Fact]
    public void Update_BodyAtThirtyDegreesIntoTheMainRoomsEastWall_SlidesNorthAlongItItsRadiusAway()
    {
        // Heading 60° (east-north-east): 30° from the east wall's normal. The body meets the wall
        // (x = 142.1) after about 1.5 s, then slides north along it; the northward part of the walk,
        // 1 m/s, is the same before and after the contact, so after 2 s the mover is 2 m north.
        const float wallX = 142.1f;
        var mode = new PlayerMovementMode(HoltburgEngine(), new Vector3(139f, 10f, 94f), 0xA9B40143u, MathF.PI / 3f, MovementOptions.Player);
        var walk = new MovementIntent(1f, 0f, 0f, false);

        int slid = 0;
        CharacterStep last = default;
        for (int i = 0; i < 60; i++)
        {
            last = mode.Update(walk, Frame);
            last.RefusedSteps.Should().Be(0, $"frame {i}: sliding is not a refusal; {last}");
            slid += last.SlidSteps;
            (wallX - mode.Position.X).Should().BeGreaterThanOrEqualTo(MoverBody.Player.Radius - 1e-3f, $"frame {i}: the body stays its radius off the wall, at {mode.Position}");
        }

        slid.Should().BeInRange(13, 16, "the last 0.49 s of 2 s are along the wall");
        mode.Position.X.Should().BeApproximately(wallX - MoverBody.Player.Radius, 1e-3f, "in contact with the wall");
        mode.Position.Y.Should().BeApproximately(12f, 1e-3f, "2 s at 1 m/s north, free and sliding alike");
        mode.CellId.Should().Be(0xA9B40143u);
        mode.Position.Z.Should().Be(94f);
        last.SlidSteps.Should().Be(1, $"{last}");
        last.LastSlideNormal.X.Should().BeApproximately(-1f, 1e-5f, $"the east wall's normal points west, at the mover: {last.LastSlideNormal}");
        last.LastSlideNormal.Y.Should().BeApproximately(0f, 1e-5f, $"{last.LastSlideNormal}");
        last.LastSlideNormal.Z.Should().Be(0f, "a wall's normal is horizontal");
    }

    [Fact]
    public void Update_BodyIntoTheMainRoomsNorthEastCorner_StopsThereAsAWallFrameAfterFrame()
    {
        // As above, on until the slide meets the wall under 0x0142's opening (y = 13.1): a concave
        // corner, which stops the body at once; pushing on, it stays put bit for bit.
        var mode = new PlayerMovementMode(HoltburgEngine(), new Vector3(139f, 10f, 94f), 0xA9B40143u, MathF.PI / 3f, MovementOptions.Player);
        var walk = new MovementIntent(1f, 0f, 0f, false);
        for (int i = 0; i < 100; i++)
        {
            mode.Update(walk, Frame);
        }

        Vector3 corner = mode.Position;
        corner.X.Should().BeApproximately(142.1f - MoverBody.Player.Radius, 1e-3f, $"at {corner}");
        corner.Y.Should().BeApproximately(13.1f - MoverBody.Player.Radius, 1e-3f, $"at {corner}");
        for (int i = 0; i < 30; i++)
        {
            CharacterStep frame = mode.Update(walk, Frame);
            frame.RefusedSteps.Should().Be(1, $"frame {i}: {frame}");
            frame.LastRefusal.Should().Be(ResolveOutcome.Wall, $"frame {i}: the engine stops the body at once in the corner; {frame}");
            frame.SlidSteps.Should().Be(0, $"frame {i}: {frame}");
            frame.LastRefusalNormal.Z.Should().Be(0f, $"frame {i}: a wall's normal; {frame}");
            frame.LastRefusalNormal.Length().Should().BeApproximately(1f, 1e-5f, $"frame {i}: {frame}");
            mode.Position.Should().Be(corner, $"frame {i}: no jitter in the corner");
        }
    }

    [Fact]
    public void Update_NoFloorUnderTheMover_GravityAccumulatesUntilTheGroundIsReached()
    {
        // A shaft 0x0101 (no floor) over a second shaft 0x0102 (opening at z 0) over a cellar 0x0103
        // (opening at −5, floor at −5.2). The mover starts 10 m up in the top shaft.
        var origin = new Vector3(96f, 96f, 0f);
        PhysicsEngine engine = Engine(
            Heights((_, _) => 0),
            Cell(0xA9B40101u, origin, null, (0x0102, 0f, true)),
            Cell(0xA9B40102u, origin, null, (0x0101, 0f, false), (0x0103, -5f, true)),
            Cell(0xA9B40103u, origin, -5.2f, (0x0102, -5f, false)));
        var mode = new PlayerMovementMode(engine, new Vector3(96f, 96f, 10f), 0xA9B40101u, 0f);

        mode.Update(Idle, Frame);
        mode.IsOnGround.Should().BeFalse("nothing is under the mover");
        float expectedZ = 10f, expectedSpeed = 0f;
        int airborne = 0;
        while (!mode.IsOnGround)
        {
            airborne.Should().BeLessThan(200, "the mover must land");
            expectedSpeed = MathF.Max(expectedSpeed + ((-new CharacterSettings().Gravity) * Frame), -new CharacterSettings().MaxFallSpeed);
            expectedZ += expectedSpeed * Frame;
            mode.Update(Idle, Frame);
            airborne++;
            if (!mode.IsOnGround)
            {
                mode.VerticalSpeed.Should().BeApproximately(-9.8f * airborne / 30f, 1e-3f, $"airborne frame {airborne}: speed grows 9.8 m/s each second");
                mode.Position.Z.Should().BeApproximately(expectedZ, 1e-3f, $"airborne frame {airborne}");
                mode.CellId.Should().Be(0xA9B40101u);
            }
        }

        expectedZ.Should().BeLessThanOrEqualTo(0.5f + 1e-3f, "it lands once it falls to within a step of the opening");
        airborne.Should().BeGreaterThan(30, "10 m take about 1.4 s");
        mode.CellId.Should().Be(0xA9B40103u, "landed in the cellar");
        mode.Position.Z.Should().Be(-5.2f);
        mode.VerticalSpeed.Should().Be(0f, "gravity stops on the ground");
        for (int i = 0; i < 100; i++)
        {
            mode.Update(Idle, Frame);
            mode.Position.Z.Should().Be(-5.2f, $"frame {i} after landing");
            mode.IsOnGround.Should().BeTrue();
        }
    }

    [Fact]
    public void Update_FallingLong_SpeedClampsAtFiftyMetresPerSecond()
    {
        PhysicsEngine engine = Engine(Heights((_, _) => 0), Cell(0xA9B40101u, new Vector3(96f, 96f, 0f), null));
        var mode = new PlayerMovementMode(engine, new Vector3(96f, 96f, 5000f), 0xA9B40101u, 0f);

        for (int i = 0; i < 300; i++)
        {
            mode.Update(Idle, Frame);
            mode.VerticalSpeed.Should().BeGreaterThanOrEqualTo(-new CharacterSettings().MaxFallSpeed, $"frame {i}");
        }

        mode.IsOnGround.Should().BeFalse();
        mode.VerticalSpeed.Should().Be(-new CharacterSettings().MaxFallSpeed, "after 10 s the unclamped speed would be 98 m/s");
    }

    [Theory]
    [InlineData(-30f, 50f, 94f, 0xA8B40001u)] // on a hill west of Holtburg
    [InlineData(139f, 10f, 94f, 0xA9B40143u)] // the cottage's main room
    [InlineData(159f, 8.4f, 90f, 0xA9B40174u)] // building B's cellar
    public void Update_StandingStillTenThousandFrames_DoesNotDrift(float x, float y, float z, uint cellId)
    {
        var world = new HoltburgWorld();
        var engine = new PhysicsEngine(HoltburgWorld.Holtburg);
        engine.AddLandblock(0xA8B4FFFFu, world.Terrain(0xA8B4FFFFu), []);
        engine.AddLandblock(HoltburgWorld.Holtburg, world.Terrain(HoltburgWorld.Holtburg), world.Cells.Select(c => new CellSurface(c.CellId, c.EnvCell, c.CellStruct)).ToList());
        var mode = new PlayerMovementMode(engine, new Vector3(x, y, z), cellId, 1f);
        mode.Update(Idle, Frame);
        Vector3 settled = mode.Position;
        uint cell = mode.CellId;
        float.IsFinite(settled.Z).Should().BeTrue();

        for (int i = 0; i < 10_000; i++)
        {
            mode.Update(Idle, Frame);
            if (mode.Position != settled || mode.CellId != cell || !mode.IsOnGround)
            {
                throw new Xunit.Sdk.XunitException($"frame {i}: moved from {settled} (0x{cell:X8}) to {mode.Position} (0x{mode.CellId:X8}), on ground {mode.IsOnGround}");
            }
        }

        if (cellId >= 0xA9B40100u)
        {
            settled.Z.Should().BeApproximately(z, 2e-3f, "indoors the mover stands on the floor");
        }
        else
        {
            settled.Z.Should().Be(world.Terrain(0xA8B4FFFFu).SampleZ(x + 192f, y), "outdoors on the hill");
            settled.Z.Should().NotBe(94f, "the hill is not flat there");
        }
    }

    [Theory]
    [InlineData(1e9f)]
    [InlineData(float.MaxValue)]
    public async Task Update_HugeFrameTime_ClampedToMaxFrameSecondsAndReturnsPromptly(float seconds)
    {
        var mode = new PlayerMovementMode(Flat(50), new Vector3(96f, 96f, 50f), 0xA9B40001u, 0f);
        var capped = new PlayerMovementMode(Flat(50), new Vector3(96f, 96f, 50f), 0xA9B40001u, 0f);
        var walk = new MovementIntent(1f, 0f, 0f, false);

        // On a worker thread with a time limit: a regression fails here instead of hanging the suite.
        Task<CharacterStep> update = Task.Factory.StartNew(() => mode.Update(walk, seconds), TaskCreationOptions.LongRunning);
        (await Task.WhenAny(update, Task.Delay(TimeSpan.FromSeconds(10)))).Should().BeSameAs(update, $"Update(walk, {seconds}) must return; still running after 10 s");

        CharacterStep frame = await update;
        CharacterStep reference = capped.Update(walk, new CharacterSettings().MaxFrameSeconds);
        frame.Steps.Should().Be(10, $"a {seconds} s frame is clamped to {new CharacterSettings().MaxFrameSeconds} s, 10 steps of 0.1 s");
        frame.Should().Be(reference, "the clamped frame is exactly a MaxFrameSeconds frame");
        mode.Position.Should().Be(capped.Position, $"moved as far as in {new CharacterSettings().MaxFrameSeconds} s");
        mode.Position.Y.Should().BeApproximately(96f + (PlayerMovementMode.WalkSpeed * new CharacterSettings().MaxFrameSeconds), 1e-3f, $"at {mode.Position}");
    }

    [Theory]
    [InlineData(-0.1f)]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    public void Update_BadFrameTime_Throws(float seconds)
    {
        var mode = new PlayerMovementMode(Flat(50), new Vector3(96f, 96f, 50f), 0xA9B40001u, 0f);

        Action act = () => mode.Update(Idle, seconds);

        act.Should().Throw<ArgumentOutOfRangeException>().WithMessage("*frame time*");
    }

    [Fact]
    public void Update_StepDownOffACliff_FallsUnderGravityAndLandsOnTheGround()
    {
        // A cliff: 300 m for x ≤ 96 (vertex columns 0..4), 0 m from x = 120; walking east off its edge
        // drops 1.7 m per 0.13 m frame move, more than the player's 1.5 m step down.
        float[] table = new float[256];
        table[1] = 300f;
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, new TerrainSurface(Heights((x, _) => x <= 4 ? 1 : 0), table, Holtburg), []);
        var mode = new PlayerMovementMode(engine, new Vector3(95f, 50f, 300f), 0xA9B40000u, MathF.PI / 2f, MovementOptions.Player with { EdgeSlide = false });

        int frame = 0, airborne = 0;
        float lowestAirborneZ = float.MaxValue;
        while (frame < 600 && (airborne == 0 || !mode.IsOnGround))
        {
            mode.Update(new MovementIntent(1f, 0f, 0f, true), Frame);
            frame++;
            if (!mode.IsOnGround)
            {
                airborne++;
                lowestAirborneZ = MathF.Min(lowestAirborneZ, mode.Position.Z);
                if (airborne > 1)
                {
                    mode.VerticalSpeed.Should().BeLessThan(0f, $"frame {frame}: falling (the frame it leaves the ground it has no vertical speed yet)");
                }

                float ground = engine.Resolve(mode.Position, mode.CellId, Vector3.Zero, 0f).Position.Z;
                mode.Position.Z.Should().BeGreaterThan(ground, $"frame {frame}: an airborne mover is above the ground ({ground} m)");
            }
        }

        airborne.Should().BeGreaterThan(10, "stepping off the cliff leaves the ground");
        mode.IsOnGround.Should().BeTrue($"landed after {frame} frames");
        float landed = engine.Resolve(mode.Position, mode.CellId, Vector3.Zero, 0f).Position.Z;
        mode.Position.Z.Should().BeApproximately(landed, 1e-4f, "on the ground under it");
        mode.VerticalSpeed.Should().Be(0f);

        // The literal engine walks the same edge with no airborne frame at all.
        var literal = new PlayerMovementMode(engine, new Vector3(95f, 50f, 300f), 0xA9B40000u, MathF.PI / 2f);
        for (int i = 0; i < frame; i++)
        {
            literal.Update(new MovementIntent(1f, 0f, 0f, true), Frame);
            literal.IsOnGround.Should().BeTrue($"literal frame {i}");
        }
    }

    [Fact]
    public void Update_StepDownIndoorShaft_FallsToTheCellarFloorAndLands()
    {
        var world = new HoltburgWorld();
        var engine = new PhysicsEngine(HoltburgWorld.Holtburg);
        engine.AddLandblock(HoltburgWorld.Holtburg, new TerrainSurface(Heights((_, _) => 94), LinearTable(), HoltburgWorld.Holtburg),
            world.Cells.Select(c => new CellSurface(c.CellId, c.EnvCell, c.CellStruct)).ToList());

        // Building B's main room 0x0171, walking west over its cellar shaft (x 152.93–154.93).
        var mode = new PlayerMovementMode(engine, new Vector3(155.3f, 8.4f, 94f), 0xA9B40171u, -MathF.PI / 2f, MovementOptions.Player with { EdgeSlide = false });
        int frame = 0, airborne = 0;
        while (frame < 300 && (airborne == 0 || !mode.IsOnGround))
        {
            mode.Update(new MovementIntent(airborne == 0 ? 1f : 0f, 0f, 0f, false), Frame);
            frame++;
            airborne += mode.IsOnGround ? 0 : 1;
        }

        airborne.Should().BeInRange(24, 30, "4 m under gravity take about 0.9 s");
        mode.IsOnGround.Should().BeTrue();
        mode.CellId.Should().Be(0xA9B40174u);
        mode.Position.Z.Should().BeApproximately(90.001f, 1e-3f, "the cellar floor's Z");
    }

    [Fact]
    public void Update_WithAMoverId_PassesItsOwnCylinderStopsAtAnothersAndNamesItTouched()
    {
        PhysicsEngine engine = Flat(50);
        var start = new Vector3(96f, 96f, 50f);
        MoverShape cylinder = MoverShape.Cylinder(0.48f, 1.835f);
        engine.Movers.Add(7u, cylinder, start, 0xA9B40025u, Quaternion.Identity, MoverState.Player);
        engine.Movers.Add(8u, cylinder, start + new Vector3(0f, 2f, 0f), 0xA9B40025u, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        var mode = new PlayerMovementMode(engine, start, 0xA9B40025u, 0f, MovementOptions.Player) { MoverId = 7u };

        var touched = new List<uint[]>();
        for (int i = 0; i < 30; i++)
        {
            mode.Update(new MovementIntent(1f, 0f, 0f, false), Frame);
            touched.Add(mode.Touched.ToArray());
        }

        mode.Position.Y.Should().BeApproximately(96f + 2f - 0.96f, 1e-3f, $"its own cylinder (mover 7, where it starts) does not stop it; mover 8's stops its body two radii short, at {mode.Position}");
        touched[0].Should().BeEmpty("the first frame touches nothing but itself, which is not named");
        touched[^1].Should().Equal([8u], "stopped at mover 8, it names it touched");
        touched.Should().OnlyContain(t => !t.Contains(7u), "never itself");
        new PlayerMovementMode(engine, start, 0xA9B40025u, 0f, MovementOptions.Player).Touched.Length.Should().Be(0, "without a mover id nothing is recorded");
    }

    [Fact]
    public void UndoLastUpdate_PutsPositionCellFootingAndVerticalSpeedBack_KeepsTheHeading()
    {
        var mode = new PlayerMovementMode(Flat(50), new Vector3(96f, 96f, 50f), 0xA9B40025u, 0f, MovementOptions.Player);
        mode.Update(new MovementIntent(1f, 0f, 0f, false), Frame);
        (Vector3 position, uint cell, bool ground, float speed) = (mode.Position, mode.CellId, mode.IsOnGround, mode.VerticalSpeed);

        mode.Update(new MovementIntent(1f, 0f, 0.5f, false, Jump: true), Frame);
        mode.IsOnGround.Should().BeFalse("it jumped");
        float heading = mode.Heading;
        mode.UndoLastUpdate();

        (mode.Position, mode.CellId, mode.IsOnGround, mode.VerticalSpeed).Should().Be((position, cell, ground, speed), "back where the frame found it");
        mode.Heading.Should().Be(heading, "the turn stays");
    }

    [Theory]
    [InlineData(100, 1f, 1.6357143f)]
    [InlineData(0, 1f, 0.35f)]
    [InlineData(200, 1f, 3.01f)]
    [InlineData(100, 0.5f, 0.8178571f)]
    [InlineData(100, 0f, 0.35f)]
    public void JumpHeight_IsTheGamesFormulaAtLeast35Centimetres(int skill, float power, float height)
    {
        var mode = new PlayerMovementMode(Flat(50), new Vector3(96f, 96f, 50f), 0xA9B40001u, 0f, MovementOptions.Player) { JumpSkill = skill, JumpPower = power };
        mode.JumpHeight.Should().BeApproximately(height, 1e-5f, "(skill / (skill + 1300) · 22.2 + 0.05) · power, at least 0.35 m");
        mode.Jump().Should().BeTrue();
        mode.VerticalSpeed.Should().BeApproximately(MathF.Sqrt(2f * 9.8f * height), 1e-4f, "vz = √(2 g h)");
    }

    [Fact]
    public void Jump_OnFlatGround_RisesItsHeightAndLandsAfterTheAnalyticTime()
    {
        var mode = new PlayerMovementMode(Flat(50), new Vector3(96f, 96f, 50f), 0xA9B40001u, 0f, MovementOptions.Player);
        mode.Jump().Should().BeTrue();
        mode.Jump().Should().BeFalse("not again in the air");
        float top = 50f;
        int frames = 0;
        CharacterStep first = default;
        int landings = 0;
        do
        {
            CharacterStep f = mode.Update(Idle, Frame);
            first = frames == 0 ? f : first;
            landings += f.Landings;
            top = MathF.Max(top, mode.Position.Z);
            frames++;
        }
        while (!mode.IsOnGround && frames < 200);

        double analytic = 2 * Math.Sqrt(2 * mode.JumpHeight / 9.8);
        (top - 50f).Should().BeApproximately(mode.JumpHeight, 0.02f, "the jump rises its height (sampled at 30 Hz)");
        Math.Abs((frames * Frame) - analytic).Should().BeLessThanOrEqualTo(Frame, "lands within a frame of 2√(2h/g)");
        mode.Position.Z.Should().Be(50f);
        mode.VerticalSpeed.Should().Be(0f, "a landing zeroes the downward speed");
        landings.Should().Be(1);
    }

    [Fact]
    public void Jump_UnderTheMainRoomsCeiling_HitsItsHeadZeroesItsUpwardSpeedAndLandsInTheRoom()
    {
        PhysicsEngine engine = HoltburgEngine();
        var mode = new PlayerMovementMode(engine, new Vector3(139.2f, 10.5f, 94f), 0xA9B40143u, 0f, MovementOptions.Player);
        mode.Update(Idle, Frame);
        mode.Update(new MovementIntent(0f, 0f, 0f, false, Jump: true), Frame).Jumps.Should().Be(1);
        int headHits = 0, frames = 0;
        while (!mode.IsOnGround && frames++ < 100)
        {
            float before = mode.VerticalSpeed;
            CharacterStep f = mode.Update(Idle, Frame);
            headHits += f.HeadHits;
            if (f.HeadHits > 0)
            {
                before.Should().BeGreaterThan(0f, "rising when it met the ceiling");
                mode.VerticalSpeed.Should().BeLessThanOrEqualTo(0f, "a head hit zeroes the upward speed (then gravity)");
            }

            (mode.Position.Z + 1.835f).Should().BeLessThanOrEqualTo(96.801f, "never through the ceiling at 96.8 m");
            mode.CellId.Should().Be(0xA9B40143u);
        }

        headHits.Should().Be(1);
        mode.Position.Z.Should().Be(94f);
    }

    [Theory]
    [InlineData(-1, 1f, "JumpSkill")]
    [InlineData(100, 1.5f, "JumpPower")]
    [InlineData(100, -0.1f, "JumpPower")]
    [InlineData(100, float.NaN, "JumpPower")]
    public void JumpSettings_OutOfRange_AreRefusedNamingTheSetting(int skill, float power, string name)
    {
        var mode = new PlayerMovementMode(Flat(50), new Vector3(96f, 96f, 50f), 0xA9B40001u, 0f, MovementOptions.Player);
        Action act = () => { mode.JumpSkill = skill; mode.JumpPower = power; };
        act.Should().Throw<ArgumentOutOfRangeException>().Which.ParamName.Should().Be(name);
    }
}
