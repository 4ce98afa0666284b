using System.Numerics;
using AcDream.Core.Physics;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>The opt-in effects: each off and on.</summary>
[Trait("Mutation", "PortalTraversal")]
public class MovementOptionsTests
{
    private const float Step = 0.5f;
    private const float GroundZ = 94f;

    private static PhysicsEngine HoltburgEngine(TerrainSurface? terrain = null)
    {
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, terrain ?? FlatTerrain(GroundZ), HoltburgCells.Surfaces());
        engine.AddLandblock(0xA9B3FFFFu, FlatTerrain(GroundZ, 0xA9B3FFFFu), []);
        return engine;
    }

    /// <summary>Terrain with a 20 m cliff: x ≤ 96 at 20 + 94 m, beyond it 94 m (a 20 m drop over one 24 m cell).</summary>
    private static PhysicsEngine CliffEngine(out float top)
    {
        float[] table = ConstantTable(GroundZ);
        table[1] = GroundZ + 20f;
        top = table[1];
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, new TerrainSurface(Heights((x, _) => x <= 4 ? 1 : 0), table, Holtburg), []);
        return engine;
    }

    [Fact]
    public void StepDown_Off_SnapsDownTheCliff_On_LeavesMoverAirborne()
    {
        PhysicsEngine engine = CliffEngine(out float top);
        var pos = new Vector3(95.5f, 50, top);
        var delta = new Vector3(4f, 0, 0); // to x 99.5: 3.5 m into the slope cell, 2.9 m lower

        ResolveResult snapped = engine.Resolve(pos, 0, delta, Step);
        ResolveResult airborne = engine.Resolve(pos, 0, delta, Step, new MovementOptions { StepDownHeight = 1.5f });

        snapped.IsOnGround.Should().BeTrue();
        snapped.Position.Z.Should().BeApproximately(top - (20f * 3.5f / 24f), 1e-3f);
        airborne.IsOnGround.Should().BeFalse("the ground is 2.9 m below, more than the 1.5 m step down");
        airborne.Position.Should().Be(new Vector3(99.5f, 50, top), "XY moves, Z is kept for the caller's gravity");
        airborne.CellId.Should().Be(snapped.CellId);
    }

    [Fact]
    public void StepDown_WithinHeight_SnapsLikeWalkingDownhill()
    {
        PhysicsEngine engine = CliffEngine(out float top);
        ResolveResult r = engine.Resolve(new Vector3(95.5f, 50, top), 0, new Vector3(1f, 0, 0), Step, new MovementOptions { StepDownHeight = 1.5f });
        r.IsOnGround.Should().BeTrue("0.4 m down is within the step down");
        r.Position.Z.Should().BeApproximately(top - (20f * 0.5f / 24f), 1e-3f);
    }

    [Fact]
    public void StepDown_FallingMover_LandsWhenZReachesGround()
    {
        // A caller's gravity loop, passing StepDownHeight 0 while airborne.
        PhysicsEngine engine = CliffEngine(out float top);
        var pos = new Vector3(95.5f, 50, top);
        ResolveResult r = engine.Resolve(pos, 0, new Vector3(30f, 0, 0), Step, new MovementOptions { StepDownHeight = 1.5f });
        r.IsOnGround.Should().BeFalse();

        float velocity = 0f;
        int frames = 0;
        while (!r.IsOnGround && frames < 300)
        {
            velocity = MathF.Max(velocity - (9.8f / 30f), -50f);
            Vector3 fallen = r.Position with { Z = r.Position.Z + (velocity / 30f) };
            r = engine.Resolve(fallen, r.CellId, Vector3.Zero, Step, new MovementOptions { StepDownHeight = 0f });
            frames++;
            if (!r.IsOnGround)
            {
                r.Position.Z.Should().BeGreaterThan(GroundZ, $"frame {frames}: an airborne mover is above the ground");
            }
        }

        r.IsOnGround.Should().BeTrue($"landed after {frames} frames");
        r.Position.Z.Should().Be(GroundZ);
        frames.Should().BeInRange(55, 62, "a 20 m fall under 9.8 m/s² takes about 2.02 s = 61 frames at 30 Hz");
    }

    [Fact]
    public void StepDown_IndoorShaft_AirborneOverCellarThenLands()
    {
        PhysicsEngine engine = HoltburgEngine();
        var options = new MovementOptions { StepDownHeight = 1.5f };

        ResolveResult r = engine.Resolve(new Vector3(155.2f, 8f, GroundZ), 0xA9B40171u, new Vector3(-0.5f, 0, 0), Step, options);

        r.IsOnGround.Should().BeFalse("the cellar floor is 4 m below the shaft's top");
        r.CellId.Should().Be(0xA9B40174u, "airborne over the cellar 0x0174, whose floor is below");
        r.Position.Z.Should().Be(GroundZ);

        ResolveResult landed = engine.Resolve(r.Position with { Z = 90.0f }, r.CellId, Vector3.Zero, Step, new MovementOptions { StepDownHeight = 0f });
        landed.IsOnGround.Should().BeTrue();
        landed.Position.Z.Should().BeApproximately(90.001f, 1e-4f);
        landed.CellId.Should().Be(0xA9B40174u);
    }

    [Fact]
    public void WalkableSlope_Off_ClimbsSteepHill_On_Rejects()
    {
        // Rise of 1 per 0.6 horizontal (normal Z 0.51 < FloorZ): 40 m over a 24 m cell.
        float[] table = ConstantTable(0f);
        table[1] = 40f;
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, new TerrainSurface(Heights((x, _) => x >= 5 ? 1 : 0), table, Holtburg), []);
        var pos = new Vector3(96.05f, 50, 40f * 0.05f / 24f);
        var delta = new Vector3(0.2f, 0, 0); // climbs 0.33 m: within the step height

        ResolveResult off = engine.Resolve(pos, 0, delta, Step);
        ResolveResult on = engine.Resolve(pos, 0, delta, Step, new MovementOptions { WalkableSlope = true });
        ResolveResult down = engine.Resolve(pos, 0, -delta, Step, new MovementOptions { WalkableSlope = true });

        off.Position.X.Should().BeApproximately(96.25f, 1e-4f, "the spec only limits the step height");
        on.Position.Should().Be(pos, "the game forbids climbing a slope with normal Z below FloorZ");
        down.Position.X.Should().BeApproximately(95.85f, 1e-4f, "going down a steep slope is allowed: the mover never freezes");
    }

    [Fact]
    public void WalkableSlope_WalkableHill_IsClimbedEitherWay()
    {
        float[] table = ConstantTable(0f);
        table[1] = 10f; // 10 m over 24 m: normal Z 0.92
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, new TerrainSurface(Heights((x, _) => x >= 5 ? 1 : 0), table, Holtburg), []);
        var pos = new Vector3(96.05f, 50, 10f * 0.05f / 24f);
        engine.Resolve(pos, 0, new Vector3(0.2f, 0, 0), Step, new MovementOptions { WalkableSlope = true })
            .Should().Be(engine.Resolve(pos, 0, new Vector3(0.2f, 0, 0), Step));
    }

    [Fact]
    public void Sweep_Off_SkipsARidge_On_StopsAtItsFoot()
    {
        // A 60 m ridge along vertex column x = 4 (x = 96): both sides at 0 m.
        float[] table = ConstantTable(0f);
        table[1] = 60f;
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, new TerrainSurface(Heights((x, _) => x == 4 ? 1 : 0), table, Holtburg), []);
        var pos = new Vector3(60f, 50, 0);
        var delta = new Vector3(72f, 0, 0); // to x 132, level with the start

        ResolveResult endPoint = engine.Resolve(pos, 0, delta, Step);
        ResolveResult swept = engine.Resolve(pos, 0, delta, Step, new MovementOptions { SweepStepLength = 0.48f });

        endPoint.Position.X.Should().Be(132f, "the end-point check sees only level ground at the end");
        swept.Position.X.Should().BeLessThan(73f, "sub-steps of 0.48 m climb 1.2 m each on the 2.5:1 ridge and are stopped at its foot");
        swept.Position.X.Should().BeGreaterThan(71.9f, "the mover walks up to the foot of the ridge, x 72");
        swept.IsOnGround.Should().BeTrue();
    }

    [Fact]
    public void Sweep_ShortMove_IsOneStepIdenticalToLiteral()
    {
        PhysicsEngine engine = HoltburgEngine();
        var pos = new Vector3(100f, 50f, GroundZ);
        engine.Resolve(pos, 0, new Vector3(0.3f, 0.2f, 0), Step, new MovementOptions { SweepStepLength = 0.48f })
            .Should().Be(engine.Resolve(pos, 0, new Vector3(0.3f, 0.2f, 0), Step));
    }

    [Fact]
    public void Sweep_LongIndoorMove_PassesDoorwaysStepByStep()
    {
        // 2.4 m from outdoors through the west door into the main room in one call.
        PhysicsEngine engine = HoltburgEngine();
        ResolveResult r = engine.Resolve(new Vector3(135.5f, 5.15f, GroundZ), 0, new Vector3(2.4f, 0, 0), Step, new MovementOptions { SweepStepLength = 0.48f });
        r.CellId.Should().Be(0xA9B40143u);
        r.Position.X.Should().BeApproximately(137.9f, 1e-3f);
    }

    [Fact]
    public void DoorsOnly_Off_EntersThroughWall_On_Rejects()
    {
        // The cottage's main room 0x0143 starts at y 3.9; walking north into it from outdoors at x 138 crosses its south wall.
        PhysicsEngine engine = HoltburgEngine();
        var pos = new Vector3(138f, 3.6f, GroundZ);
        var delta = new Vector3(0, 0.5f, 0);

        engine.Resolve(pos, 0, delta, Step).CellId.Should().Be(0xA9B40143u, "the spec enters wherever a floor lies under the mover");
        engine.Resolve(pos, 0, delta, Step, new MovementOptions { DoorsOnly = true })
            .Should().Be(new ResolveResult(pos, 0xA9B40029u, true) { Outcome = ResolveOutcome.OuterWall }, "the outer wall stops the mover at (138, 3.6), outdoor cell cx 5 cy 0: 0x29");
    }

    [Fact]
    public void DoorsOnly_On_EntersThroughTheDoor()
    {
        PhysicsEngine engine = HoltburgEngine();
        var options = new MovementOptions { DoorsOnly = true };
        var pos = new Vector3(136.1f, 5.15f, GroundZ);
        ResolveResult r = engine.Resolve(pos, 0, new Vector3(0.3f, 0, 0), Step, options);
        r.CellId.Should().Be(0xA9B40145u, "across 0x0145's portal to the outdoors");

        // North door of building B (0x0170), whose outdoor portal leans ~6°.
        ResolveResult b = engine.Resolve(new Vector3(155.4f, 16.5f, GroundZ), 0, new Vector3(0, -0.6f, 0), Step, options);
        b.CellId.Should().Be(0xA9B40170u);
    }

    [Fact]
    public void Resolve_AnyEffects_AllocatesNothing()
    {
        PhysicsEngine engine = HoltburgEngine(new TerrainSurface(RandomHeights(new Random(2)), NonLinearTable(), Holtburg));
        MovementOptions[] configurations =
        [
            default,
            new() { StepDownHeight = 1.5f },
            new() { WalkableSlope = true },
            new() { SweepStepLength = 0.48f },
            new() { DoorsOnly = true },
            MovementOptions.Player,
        ];
        foreach (MovementOptions options in configurations)
        {
            // One full pass first, so JIT tiering and on-stack replacement of the loop are mostly done,
            // then count up to three more passes: steady state must allocate nothing. A per-call
            // allocation shows in every pass; the runtime's own one-time work (a late tier-up, seen
            // once in a full-suite run) in one at most, so the quietest pass must be 0 B.
            Run(engine, options);
            var passes = new List<long>();
            float sink = 0f;
            for (int pass = 0; pass < 3 && (passes.Count == 0 || passes[^1] != 0); pass++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                sink += Run(engine, options);
                passes.Add(GC.GetAllocatedBytesForCurrentThread() - before);
            }

            passes.Min().Should().Be(0, $"15,000 resolves with {options} allocated {string.Join(", ", passes)} bytes in successive passes (sink {sink})");
        }

        static float Run(PhysicsEngine engine, MovementOptions options)
        {
            var outdoor = new Vector3(100f, 100f, 100f);
            var indoor = new Vector3(138f, 6f, GroundZ);
            float sink = 0f;
            for (int i = 0; i < 5000; i++)
            {
                sink += engine.Resolve(outdoor, 0, new Vector3(1.3f, 0.4f, 0), Step, options).Position.Z;
                sink += engine.Resolve(indoor, 0xA9B40143u, new Vector3((i % 7) * 0.1f, 0.1f, 0), Step, options).Position.Z;
                sink += engine.Resolve(new Vector3(140.3f, 6f, GroundZ), 0xA9B40143u, new Vector3(0.5f, 0, 0), Step, options).Position.Z;
            }

            return sink;
        }
    }

    [Theory]
    [InlineData(0.1f)]
    [InlineData(0.45f)]
    [InlineData(0.6f)]
    [InlineData(1.0f)]
    [InlineData(2.0f)]
    public void DoorsOnly_MoveLongerThanTheDoorCell_PassesItIntoTheRoom(float stepLength)
    {
        // 0x0145 is 0.4 m deep (x 136.3..136.7): a longer move jumps from the terrain past it into 0x0143.
        PhysicsEngine engine = HoltburgEngine();
        foreach (MovementOptions options in new[] { new MovementOptions { DoorsOnly = true }, MovementOptions.Player })
        {
            for (int start = 0; start < 20; start++)
            {
                var pos = new Vector3(134.0f + (start * 0.05f), 5.15f, GroundZ);
                uint cell = 0xA9B40000u;
                for (int frame = 0; frame < 80 && pos.X < 138f; frame++)
                {
                    ResolveResult r = engine.Resolve(pos, cell, new Vector3(stepLength, 0, 0), Step, options);
                    r.Position.Should().NotBe(pos, $"{options}, step {stepLength} m, start x {134.0f + (start * 0.05f)}: stuck at {pos} in 0x{cell:X8}");
                    (pos, cell) = (r.Position, r.CellId);
                }

                cell.Should().Be(0xA9B40143u, $"{options}, step {stepLength} m: through the door into the main room");
            }
        }
    }

    [Fact]
    public void DoorsOnly_LongMoveThroughTheWallBesideTheDoor_IsRejected()
    {
        // Same 1 m move as through the door, but at y 7, beside the doorway (y 4.2..6.1): the wall.
        PhysicsEngine engine = HoltburgEngine();
        var pos = new Vector3(135.9f, 7f, GroundZ);
        engine.Resolve(pos, 0, new Vector3(1f, 0, 0), Step, new MovementOptions { DoorsOnly = true }).Position.Should().Be(pos);
    }
}
