using System.Numerics;
using AcDream.Core.Physics;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The character of the library (<see cref="Character"/>): settings checked by name, a jump under the cottage's ceiling,
/// a fall timed against gravity, a place on a floor, in the air and inside a wall, an undo, long frames, the touched
/// movers merged across steps in the order met, and no allocation per update; in both world frames.
/// </summary>
public class CharacterTests(ITestOutputHelper output)
{
    private const uint MainRoom = 0xA9B40143;
    private const float Frame = 1f / 30f;

    public static TheoryData<string> Frames => new() { "global", "centred" };

    [Theory]
    [InlineData("StepUpHeight")]
    [InlineData("Gravity")]
    [InlineData("MaxFallSpeed")]
    [InlineData("JumpSkill")]
    [InlineData("MaxStepSeconds")]
    [InlineData("MaxFrameSeconds")]
    public void A_setting_out_of_range_is_refused_by_name(string setting)
    {
        var good = new CharacterSettings();
        CharacterSettings bad = setting switch
        {
            "StepUpHeight" => good with { StepUpHeight = -0.1f },
            "Gravity" => good with { Gravity = float.NaN },
            "MaxFallSpeed" => good with { MaxFallSpeed = 0f },
            "JumpSkill" => good with { JumpSkill = -1 },
            "MaxStepSeconds" => good with { MaxStepSeconds = 0f },
            _ => good with { MaxFrameSeconds = 0.05f },
        };
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        Action make = () => _ = new Character(engine, bad, engine.ToWorld(TestData.Holtburg, new Vector3(100, 100, 94)), 0);
        make.Should().Throw<ArgumentOutOfRangeException>().WithParameterName("settings").WithMessage($"*settings.{setting}*");
        _ = new Character(engine, good, engine.ToWorld(TestData.Holtburg, new Vector3(100, 100, 94)), 0); // the defaults are good
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_jump_under_the_main_rooms_ceiling_hits_it_once_and_lands_on_the_floor(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        var character = new Character(engine, new CharacterSettings(), engine.ToWorld(TestData.Holtburg, new Vector3(138.5f, 6f, 94f)), MainRoom);
        character.Place(character.Position, MainRoom).IsOnGround.Should().BeTrue();
        CharacterStep step = character.Update(Frame, Vector2.Zero, jump: true);
        step.Jumps.Should().Be(1);
        int headHits = step.HeadHits, frames = 1;
        float top = 0f;
        while (!step.Landed && frames < 120)
        {
            step = character.Update(Frame, Vector2.Zero, jump: false);
            headHits += step.HeadHits;
            top = MathF.Max(top, engine.ToLandblockLocal(TestData.Holtburg, step.Position).Z + MoverBody.Player.Height);
            step.CellId.Should().Be(MainRoom, $"{frame}, frame {frames}");
            frames++;
        }

        headHits.Should().Be(1, $"{frame}: a 1.64 m jump under a ceiling 2.8 m over the floor hits it once");
        top.Should().BeInRange(96.8f - 1e-3f, 96.8f + 1e-3f, $"{frame}: the top stops at the ceiling");
        (step.IsOnGround, step.VerticalSpeed, engine.ToLandblockLocal(TestData.Holtburg, step.Position).Z).Should().Be((true, 0f, 94f), $"{frame}: landed on the floor");
        output.WriteLine($"[{frame}] top {top:F5} m, landed after {frames} frames");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_fall_of_ten_metres_lands_within_a_frame_of_the_analytic_time(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        Vector3 high = engine.ToWorld(TestData.Holtburg, new Vector3(60f, 60f, 104f));
        var character = new Character(engine, new CharacterSettings(), high, 0);
        character.Place(high, 0).IsOnGround.Should().BeFalse("ten metres above the ground is not within a step of it");
        int frames = 0;
        CharacterStep step;
        do
        {
            step = character.Update(Frame, Vector2.Zero, jump: false);
            frames++;
        }
        while (!step.IsOnGround && frames < 300);

        double analytic = Math.Sqrt(2 * 10 / 9.8);
        (frames * Frame).Should().BeInRange((float)analytic - Frame, (float)analytic + Frame, $"{frame}: lands at √(2h/g) = {analytic:F3} s");
        (step.Landed, engine.ToLandblockLocal(TestData.Holtburg, step.Position).Z, step.VerticalSpeed).Should().Be((true, 94f, 0f), $"{frame}: on the ground");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void Place_settles_on_a_floor_within_its_step_stays_in_the_air_above_and_refuses_a_wall(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        var character = new Character(engine, new CharacterSettings(), engine.ToWorld(TestData.Holtburg, new Vector3(100, 100, 94)), 0);
        ResolveResult onFloor = character.Place(engine.ToWorld(TestData.Holtburg, new Vector3(139.2f, 10.5f, 94.4f)), MainRoom);
        (onFloor.IsOnGround, onFloor.CellId, engine.ToLandblockLocal(TestData.Holtburg, onFloor.Position).Z).Should().Be((true, MainRoom, 94f), $"{frame}: 0.4 m above the floor settles on it");
        (character.Position, character.IsOnGround, character.VerticalSpeed).Should().Be((onFloor.Position, true, 0f));

        ResolveResult inAir = character.Place(engine.ToWorld(TestData.Holtburg, new Vector3(60f, 60f, 97f)), 0);
        (inAir.IsOnGround, engine.ToLandblockLocal(TestData.Holtburg, inAir.Position).Z).Should().Be((false, 97f), $"{frame}: 3 m above the ground stays in the air");

        // Inside the cottage's west wall, from outdoors (the wall runs north-south at x ≈ 136.3 m).
        Vector3 before = character.Position;
        Action inWall = () => character.Place(engine.ToWorld(TestData.Holtburg, new Vector3(136.3f, 8f, 94f)), MainRoom);
        inWall.Should().Throw<ArgumentException>().WithParameterName("position").WithMessage("*inside a wall*");
        character.Position.Should().Be(before, "a refused place changes nothing");
    }

    [Fact]
    public void Undo_takes_the_last_update_back_jump_included()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        var character = new Character(engine, new CharacterSettings(), engine.ToWorld(TestData.Holtburg, new Vector3(60, 60, 94)), 0);
        character.Update(Frame, new Vector2(0f, 4f), jump: false);
        (Vector3, uint, bool, float) before = (character.Position, character.CellId, character.IsOnGround, character.VerticalSpeed);
        CharacterStep step = character.Update(Frame, new Vector2(4f, 0f), jump: true);
        (step.Jumps, step.IsOnGround).Should().Be((1, false));
        character.Undo();
        (character.Position, character.CellId, character.IsOnGround, character.VerticalSpeed).Should().Be(before);
    }

    [Fact]
    public void A_long_frame_is_clamped_and_split_into_steps_and_a_zero_frame_moves_nothing()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        Vector3 start = engine.ToWorld(TestData.Holtburg, new Vector3(40, 40, 94));
        var character = new Character(engine, new CharacterSettings(), start, 0);
        character.Update(0f, new Vector2(3f, 0f), jump: true).Should().Be(new CharacterStep { Position = start, CellId = character.CellId, IsOnGround = true });
        CharacterStep step = character.Update(5f, new Vector2(2f, 0f), jump: false);
        step.Steps.Should().Be(10, "5 s is clamped to 1 s, in steps of 0.1 s");
        (step.Position.X - start.X).Should().BeApproximately(2f, 1e-3f, "1 s at 2 m/s");
        Action bad = () => character.Update(-1f, Vector2.Zero, false);
        bad.Should().Throw<ArgumentOutOfRangeException>().WithParameterName("seconds");
        Action nan = () => character.Update(Frame, new Vector2(float.NaN, 0f), false);
        nan.Should().Throw<ArgumentOutOfRangeException>().WithParameterName("velocity");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void Each_slid_step_names_its_normal_in_order(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        var character = new Character(engine, new CharacterSettings(), engine.ToWorld(TestData.Holtburg, new Vector3(139f, 6f, 94f)), MainRoom);
        CharacterStep step = character.Update(1f, new Vector2(1f, -3f), jump: false); // 10 steps, into the room's south wall at a slant
        step.SlidSteps.Should().BeGreaterThan(1, $"{frame}: it reaches the wall and slides along it: {step}");
        character.SlideNormals.Length.Should().Be(step.SlidSteps);
        character.SlideNormals[^1].Should().Be(step.LastSlideNormal);
        foreach (Vector3 normal in character.SlideNormals)
        {
            (normal.Z, normal.Length()).Should().Be((0f, normal.Length()), "a wall's normal is horizontal");
            normal.Length().Should().BeApproximately(1f, 1e-5f);
            normal.Y.Should().BeGreaterThan(0.9f, $"{frame}: the south wall faces north, towards the character");
        }

        character.Update(1f / 30f, Vector2.Zero, jump: false);
        character.SlideNormals.Length.Should().Be(0, "each update starts its own list");
    }

    [Fact]
    public void The_movers_touched_are_merged_across_steps_in_the_order_met_and_an_update_allocates_nothing()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        Vector3 Local(float x, float y) => engine.ToWorld(TestData.Holtburg, new Vector3(x, y, 94f));
        engine.Movers.Add(1, MoverShape.Cylinder(0.48f, 1.835f), Local(40f, 40f), 0, Quaternion.Identity, MoverState.Creature);
        MoverState ghost = MoverState.Creature with { Physics = PhysicsStateFlags.Ethereal };
        engine.Movers.Add(21, MoverShape.Cylinder(0.2f, 1f), Local(40f, 40.9f), 0, Quaternion.Identity, ghost); // met second
        engine.Movers.Add(20, MoverShape.Cylinder(0.2f, 1f), Local(40f, 40.5f), 0, Quaternion.Identity, ghost); // met first
        engine.Movers.Commit();
        var character = new Character(engine, new CharacterSettings { MoverId = 1 }, Local(40f, 40f), 0);
        Span<uint> touched = stackalloc uint[4];
        CharacterStep step = character.Update(0.3f, new Vector2(0f, 4f), jump: false, touched);
        step.Steps.Should().Be(3);
        touched[..step.TouchedCount].ToArray().Should().Equal([20u, 21u], "each once, in the order met along the path, not the order registered");

        character.Update(Frame, new Vector2(0f, -1f), false, touched); // warm
        long allocated = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            character.Update(Frame, new Vector2(i % 2 == 0 ? 1f : -1f, 0f), jump: false, touched);
        }

        (GC.GetAllocatedBytesForCurrentThread() - allocated).Should().Be(0, "an update allocates nothing");
    }
}
