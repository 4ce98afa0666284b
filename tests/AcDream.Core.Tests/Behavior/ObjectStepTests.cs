using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// An outdoor ramp object rising at 45° from its foot at x 100 (z 0 above the ground) to x 104 (4 m up), then a
/// platform to x 110, on flat ground: a point walking at it from the ground does not pass under the ramp (its floor
/// rises through the step line ahead: a rise too high); a swept mover climbs it, each sub-step that rises too high
/// taken in halves, down to 1/16 of the sub-step (<see cref="PhysicsConstants.MaxClimbHalvings"/>). Both world frames.
/// </summary>
[Trait("Mutation", "ObjectQueries")]
public class ObjectStepTests
{
    private const float Step = 0.6f;
    private const float GroundZ = 94f;

    public static TheoryData<string> Frames => new() { "global", "centred" };

    private static (PhysicsEngine Engine, Vector3 Origin) Ramp(string frame)
    {
        var ramp = ObjectKit.Gfx(0x01000700,
            [new(0f, -1f, 0f), new(4f, -1f, 4f), new(4f, 1f, 4f), new(0f, 1f, 0f)],
            [new(4f, -1f, 4f), new(10f, -1f, 4f), new(10f, 1f, 4f), new(4f, 1f, 4f)]);
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), [], [new ObjectSurface(ramp, ObjectKit.At(new Vector3(100f, 100f, GroundZ), 0f), 0)]);
        return (engine, engine.GetLandblockOrigin(Holtburg));
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_point_walking_at_a_ramp_from_the_ground_does_not_pass_under_it(string frame)
    {
        (PhysicsEngine engine, Vector3 origin) = Ramp(frame);
        Vector3 start = origin + new Vector3(99f, 100f, GroundZ);

        // The end, x 102, lies under the ramp (2 m up): its floor rises through the feet + step line at x 100.6.
        ResolveResult r = engine.Resolve(start, 0, new Vector3(3f, 0f, 0f), Step);
        (r.Outcome, r.Position, r.SurfaceNormal).Should().Be((ResolveOutcome.StepTooHigh, start, new Vector3(-1f, 0f, 0f)), $"{frame}: {r}");

        // A move that stays below the line walks onto the ramp.
        ResolveResult onto = engine.Resolve(start, 0, new Vector3(1.5f, 0f, 0f), Step);
        onto.Outcome.Should().Be(ResolveOutcome.Moved, $"{frame}: {onto}");
        onto.Position.Z.Should().BeApproximately(GroundZ + 0.5f, 1e-4f, $"{frame}: on the ramp, 0.5 m up: {onto}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_swept_mover_climbs_the_ramp_in_halves_of_its_sub_steps(string frame)
    {
        (PhysicsEngine engine, Vector3 origin) = Ramp(frame);
        Vector3 start = origin + new Vector3(99f, 100f, GroundZ);

        // 1 m sub-steps rise 1 m on the ramp: each is taken as two halves of 0.5 m.
        ResolveResult r = engine.Resolve(start, 0, new Vector3(3f, 0f, 0f), Step, new MovementOptions { SweepStepLength = 1f });
        r.Outcome.Should().Be(ResolveOutcome.Moved, $"{frame}: {r}");
        Vector3.Distance(r.Position, origin + new Vector3(102f, 100f, GroundZ + 2f)).Should().BeLessThan(0.01f, $"{frame}: 2 m up the ramp: {r}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_sub_step_is_halved_down_to_a_sixteenth_and_no_further(string frame)
    {
        (PhysicsEngine engine, Vector3 origin) = Ramp(frame);
        Vector3 start = origin + new Vector3(99f, 100f, GroundZ);

        // One 8 m sub-step: its sixteenths (0.5 m) rise less than the step; it climbs to the platform.
        ResolveResult climbed = engine.Resolve(start, 0, new Vector3(8f, 0f, 0f), Step, new MovementOptions { SweepStepLength = 8f });
        climbed.Outcome.Should().Be(ResolveOutcome.Moved, $"{frame}: {climbed}");
        Vector3.Distance(climbed.Position, origin + new Vector3(107f, 100f, GroundZ + 4f)).Should().BeLessThan(0.01f, $"{frame}: on the platform: {climbed}");

        // One 10 m sub-step: a sixteenth (0.625 m) on the ramp rises more than the step, and is not halved again.
        ResolveResult stopped = engine.Resolve(start, 0, new Vector3(10f, 0f, 0f), Step, new MovementOptions { SweepStepLength = 10f });
        stopped.Outcome.Should().Be(ResolveOutcome.StepTooHigh, $"{frame}: {stopped}");
        Vector3.Distance(stopped.Position, origin + new Vector3(100.25f, 100f, GroundZ + 0.25f)).Should().BeLessThan(0.01f, $"{frame}: the last sixteenth that rose no more than the step: {stopped}");
    }
}
