using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// A mover in building B's shaft 0xA9B40175 beside the top landing of the cellar stair 0x01FFF174, which stands in the
/// cellar 0xA9B40174 and rises 0.164 m above the floor opening (z 93.636) into the shaft: moving into the landing, a point
/// mover and a body stand on it and never end with their feet in it, as from the cellar.
/// </summary>
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
[Trait("Mutation", "PortalTraversal")]
public class NeighbourObjectTests(ITestOutputHelper output)
{
    private const uint Shaft = 0xA9B40175, Cellar = 0xA9B40174;

    /// <summary>The landing's plane (the ramp's own: 0.8 m up per metre north), over x 153.069–154.769, y 9.853–10.353.</summary>
    private static float LandingZ(float y) => 93.4f + ((y - 9.853149f) * 0.8f);

    private static bool OverLanding(Vector3 p) => p.X >= 153.069f && p.X <= 154.769f && p.Y >= 9.853149f && p.Y <= 10.353151f;

    public static TheoryData<string, float> Movers() => new()
    {
        { "centred", 0f }, { "centred", 0.2f }, { "centred", 0.48f }, { "global", 0f }, { "global", 0.2f },
    };

    [Theory]
    [MemberData(nameof(Movers))]
    public void A_mover_in_the_shaft_moving_into_the_landing_stands_on_it_and_never_sinks_into_it(string frame, float radius)
    {
        PhysicsEngine e = RealObjects.HoltburgWithCellarStairs(frame);
        MovementOptions o = MovementOptions.Player with { Body = radius > 0 ? new MoverBody(radius, 1.2f) : null };
        int moves = 0, onLanding = 0;
        foreach (float x in new[] { 153.5f, 154f })
        {
            foreach (float y in new[] { 9.6f, 9.9f, 10.05f })
            {
                foreach (float z in new[] { 93.64f, 93.66f, 93.7f, 93.76f })
                {
                    if (z < LandingZ(y) + 0.001f)
                    {
                        continue; // (a start in the landing)
                    }

                    foreach (Vector3 d in new[] { new Vector3(0, 0.25f, 0), new Vector3(0, 0.5f, 0), new Vector3(0, 0.4f, -0.05f), new Vector3(0.1f, 0.3f, 0) })
                    {
                        Vector3 start = e.ToLandblockLocal(TestData.Holtburg, e.ToWorld(TestData.Holtburg, new Vector3(x, y, z))); // (as the frame rounds it)
                        ResolveResult r = e.Resolve(e.ToWorld(TestData.Holtburg, start), Shaft, d, 0.6f, o);
                        Vector3 end = e.ToLandblockLocal(TestData.Holtburg, r.Position);
                        string says = $"[{frame}] r {radius} from {start} in 0x{Shaft:X8} by {d}: {r} (local {end}, landing there {(OverLanding(end) ? LandingZ(end.Y) : float.NaN)})";
                        ResolveResult again = e.Resolve(r.Position, r.CellId, Vector3.Zero, 0.6f, o);
                        (again.Position, again.CellId, again.IsOnGround).Should().Be((r.Position, r.CellId, r.IsOnGround), $"re-resolved with no move: {says}");
                        r.CellId.Should().BeOneOf([Shaft, Cellar, 0xA9B40171u], says);
                        if (OverLanding(end))
                        {
                            end.Z.Should().BeGreaterThanOrEqualTo(LandingZ(end.Y) - 1e-4f, $"the feet above the landing: {says}");
                            if (r.IsOnGround)
                            {
                                end.Z.Should().BeApproximately(LandingZ(end.Y), 1e-4f, $"the only ground there is the landing: {says}");
                                onLanding++;
                            }
                        }

                        if (radius == 0f && OverLanding(end) && LandingZ(end.Y) >= z)
                        {
                            r.IsOnGround.Should().BeTrue($"a point mover steps up onto the landing: {says}");
                        }

                        moves++;
                    }
                }
            }
        }

        // (A body keeps its radius from the shaft's north wall at y 10.353: one of 0.48 m never reaches the landing's
        // part above the opening.)
        output.WriteLine($"[{frame}] r {radius}: {moves} moves, {onLanding} ended standing on the landing");
        onLanding.Should().BeGreaterThan(radius == 0f ? moves / 4 : radius < 0.3f ? 0 : -1);
    }

    [Theory]
    [InlineData("centred")]
    [InlineData("global")]
    public void Standing_on_the_landing_above_the_opening_named_in_the_shaft_stays_on_it(string frame)
    {
        PhysicsEngine e = RealObjects.HoltburgWithCellarStairs(frame);
        // (The player's body, 0.48 m, overlaps the shaft's north wall there; it stays too.)
        foreach (MovementOptions o in new[] { MovementOptions.Player, MovementOptions.Player with { Body = new MoverBody(0.2f, 1.2f) }, MovementOptions.Player with { Body = null } })
        {
            foreach (float y in new[] { 10.1f, 10.2f, 10.3f })
            {
                Vector3 at = e.ToLandblockLocal(TestData.Holtburg, e.ToWorld(TestData.Holtburg, new Vector3(154f, y, 93.7f))); // (as the frame rounds it)
                var feet = new Vector3(at.X, at.Y, LandingZ(at.Y));
                ResolveResult r = e.Resolve(e.ToWorld(TestData.Holtburg, feet), Shaft, Vector3.Zero, 0.6f, o);
                Vector3 end = e.ToLandblockLocal(TestData.Holtburg, r.Position);
                string says = $"[{frame}] {o.Body} on the landing at {feet}: {r} (local {end})";
                r.IsOnGround.Should().BeTrue(says);
                end.Z.Should().BeApproximately(feet.Z, 1e-4f, says);
                r.CellId.Should().BeOneOf([Shaft, Cellar], says);
                (end.X, end.Y).Should().Be((feet.X, feet.Y), says);
            }
        }
    }
}
