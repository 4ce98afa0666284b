using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Seeded random courses (rooms, corridors, an L-shaped room with a diagonal corner, two rooms with a
/// doorway in a shared zero-thickness wall or through a 0.4 m door cell, a room with free-standing
/// zero-thickness walls, a pillar, a parapet, a curb and a beam, a room closed off in two by a
/// zero-thickness partition; walls often split into collinear
/// pieces; every cell turned by a random yaw, some quaternions non-unit) in both world frames, a third
/// of them in landblocks at the world's far edge (0xFE, where the global frame's float spacing is
/// 3.9 mm). Movers walk chains of moves (each answer the next start) with the player's body or a random
/// one, each call checked against <see cref="ReferenceBody"/> from the same start.
/// </summary>
public class BodyReferenceCourseTests
{
    private const float Step = 0.5f;

    public static TheoryData<int, string> Frames() => new() { { 101, "centred" }, { 102, "global" } };

    [Theory]
    [MemberData(nameof(Frames))]
    public void Resolve_RandomCourses_AgreeWithTheReferenceNeverOverlapNeverTunnel(int seed, string frame)
    {
        var random = new Random(seed);
        int calls = 0, slid = 0, compared = 0, illConditioned = 0, indoorsOther = 0;
        double worstDistance = 0, worstOverlap = double.NegativeInfinity;
        foreach (BodyCourses.Kind kind in Enum.GetValues<BodyCourses.Kind>())
        {
            for (int c = 0; c < 12; c++)
            {
                int lbX = random.Next(3) == 0 ? 0xFE : random.Next(1, 254), lbY = random.Next(3) == 0 ? 0xFE : random.Next(1, 254);
                BodyCourse course = BodyCourses.Build(kind, random, lbX, lbY, global: frame == "global");
                MoverBody body = random.Next(3) == 0 ? new MoverBody(BodyCourses.Range(random, 0.2f, 0.6f), BodyCourses.Range(random, 1.0f, 2.0f)) : MoverBody.Player;
                MovementOptions options = random.Next(2) == 0 ? new MovementOptions { Body = body } : MovementOptions.Player with { Body = body };
                for (int walk = 0; walk < 4; walk++)
                {
                    (Vector3 Position, uint Cell)? start = course.RandomStart(random, body, Step, 0.01f);
                    start.Should().NotBeNull($"{course.Name}: a start clear of the walls for body r {body.Radius}");
                    (Vector3 pos, uint cell) = start!.Value;
                    float angle = random.NextSingle() * MathF.PI * 2;
                    for (int m = 0; m < 25; m++)
                    {
                        // Mostly walking-sized moves held in one direction for a while, so they slide along walls.
                        angle = random.Next(4) == 0 ? random.NextSingle() * MathF.PI * 2 : angle;
                        float length = random.Next(5) switch { 0 => 2f, 1 => 1f, 2 => 0.05f, _ => 0.3f };
                        var delta = new Vector3(MathF.Cos(angle) * length, MathF.Sin(angle) * length, 0);
                        BodyCall call = BodyCheck.Compare(course, pos, cell, delta, Step, options);
                        call.Overlap.Should().BeLessThanOrEqualTo(BodyCheck.OverlapLimit, $"overlap: {call}");
                        call.Tunnelled.Should().BeFalse($"tunnelled: {call}");
                        call.Agrees.Should().BeTrue($"end position: {call}");
                        calls++;
                        slid += call.Engine.Outcome == ResolveOutcome.Slid ? 1 : 0;
                        compared += call.WellConditioned ? 1 : 0;
                        illConditioned += call.WellConditioned ? 0 : 1;
                        indoorsOther += call.Engine.CellId != course.Areas[0].Cell ? 1 : 0;
                        worstDistance = call.WellConditioned ? Math.Max(worstDistance, call.Distance) : worstDistance;
                        worstOverlap = Math.Max(worstOverlap, call.Overlap);
                        (pos, cell) = (call.Engine.Position, call.Engine.CellId);
                    }
                }
            }
        }

        string summary = FormattableString.Invariant($"{calls} calls, {slid} slid, {compared} compared ({illConditioned} ill-conditioned), {indoorsOther} in another cell; worst |engine − reference| {worstDistance:E2} m, worst overlap {worstOverlap:E2} m");
        calls.Should().Be(Enum.GetValues<BodyCourses.Kind>().Length * 12 * 4 * 25, summary);
        slid.Should().BeGreaterThan(calls / 5, $"sliding courses: {summary}");
        compared.Should().BeGreaterThan(calls * 97 / 100, $"nearly every call is compared: {summary}");
        indoorsOther.Should().BeGreaterThan(calls / 50, $"movers pass doorways into the other rooms: {summary}");
    }
}
