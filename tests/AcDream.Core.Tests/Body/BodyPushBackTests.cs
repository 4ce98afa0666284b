using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Body;

/// <summary>
/// The slide's push back (<c>BodySweep.Slide</c>): a body that starts inside its contact radius from a wall (its radius
/// plus the skin) by more than its sink and less than four times it is first put back at the contact radius; deeper,
/// it is left where it is. A room of Holtburg (centred frame) with a wall along y = 104 from x 100 to 120; the body
/// (radius 0.48 m, 1.2 m tall) moves 2 m east along it. Its skin there: <see cref="PhysicsConstants.BodySkin"/> plus twice
/// the float spacing of its largest coordinate and reach (about 108 m), its sink half that.
/// </summary>
[Trait("Mutation", "BodySweep")]
public class BodyPushBackTests
{
    private const float GroundZ = 94f;
    private const float WallY = 104f;
    private static readonly MoverBody Body = new(0.48f, 1.2f);
    private static readonly float Skin = PhysicsConstants.BodySkin + (2f * Geometry.Spacing(105f + 2f + Body.Radius));
    private static readonly float Sink = 0.5f * Skin;

    /// <summary>The body's gap from the wall (its centre's distance less the radius) after the move, from a start <paramref name="gap"/> from it.</summary>
    private static (float Gap, ResolveResult Result) Along(float gap, Vector3 delta, float southGap = float.NaN)
    {
        var builder = new CellBuilder(0xA9B40100u).Floor(100f, 100f, 120f, 104f, GroundZ).Physics(Wall(100f, WallY, 120f, WallY, GroundZ, GroundZ + 3f));
        if (!float.IsNaN(southGap))
        {
            float southY = WallY - gap - (2f * Body.Radius) - southGap;
            builder.Physics(Wall(120f, southY, 100f, southY, GroundZ, GroundZ + 3f));
        }

        CellSurface room = builder.Build();
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [room]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        ResolveResult r = engine.Resolve(origin + new Vector3(105f, WallY - Body.Radius - gap, GroundZ), 0xA9B40100u, delta, 0.5f, new MovementOptions { Body = Body });
        return (WallY - (r.Position.Y - origin.Y) - Body.Radius, r);
    }

    [Theory]
    [InlineData(1.5f)]
    [InlineData(2f)]
    [InlineData(3f)]
    [InlineData(3.8f)]
    public void A_body_sunk_into_its_skin_by_more_than_its_sink_is_put_back_at_its_contact_radius(float sinks)
    {
        float start = Skin - (sinks * Sink);
        (float gap, ResolveResult r) = Along(start, new Vector3(2f, 0f, 0f));
        gap.Should().BeInRange(Skin - Geometry.Spacing(WallY), Skin + Geometry.Spacing(WallY), $"sunk {sinks} sinks (skin {Skin}): back at its contact radius: {r}");
        r.Outcome.Should().Be(ResolveOutcome.Slid, "it touched the wall it was put back from");
        r.SurfaceNormal.Y.Should().Be(-1f);
    }

    [Theory]
    [InlineData(0.5f)]
    [InlineData(4.5f)]
    [InlineData(8f)]
    public void A_body_sunk_by_less_than_its_sink_or_more_than_four_times_it_moves_where_it_is(float sinks)
    {
        float start = Skin - (sinks * Sink);
        (float gap, ResolveResult r) = Along(start, new Vector3(2f, 0f, 0f));
        gap.Should().BeApproximately(start, Geometry.Spacing(WallY), $"sunk {sinks} sinks (skin {Skin}): neither pushed out nor pulled in: {r}");
    }

    /// <summary>
    /// In a corridor as wide as the body with its skin on one side and half a sink less on the other: sunk two sinks into the
    /// north wall, the push back would put it 2.5 sinks into the south one, so it stays where it is.
    /// </summary>
    [Fact]
    public void A_body_whose_push_back_would_sink_it_into_another_wall_stays_where_it_is()
    {
        float start = Skin - (2f * Sink);
        (float gap, ResolveResult r) = Along(start, new Vector3(2f, 0f, 0f), southGap: Skin - (0.5f * Sink));
        gap.Should().BeApproximately(start, Geometry.Spacing(WallY), $"not pushed into the south wall: {r}");

        // With the south wall a skin farther: pushed back.
        (float free, ResolveResult r2) = Along(start, new Vector3(2f, 0f, 0f), southGap: (2f * Skin) + Sink);
        free.Should().BeApproximately(Skin, Geometry.Spacing(WallY), $"pushed back: {r2}");
    }
}
