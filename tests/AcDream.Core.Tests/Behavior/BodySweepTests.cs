using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The closed-form sweep of a body's disc against one wall segment seen from above (<c>BodySweep.SweepSegment</c>),
/// at a wall's end: a wall from (0, 0) to (10, 0), a disc of contact radius 0.5 m whose rounding sink is 20 µm (its
/// graze: 0.5 m less the sink and the contact tolerance, 0.49988 m).
/// </summary>
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class BodySweepTests
{
    private static readonly Vector2 A = new(0f, 0f), B = new(10f, 0f);

    private static WallHit Sweep(Vector2 p, Vector2 d)
    {
        var hit = WallHit.None;
        BodySweep.SweepSegment(BodyMove.Of(p, d, 0.5f, 2e-5f, 0f, 2f), A, B, 0f, ref hit);
        return hit;
    }

    /// <summary>
    /// A disc that reaches its contact radius from the wall's line beyond the wall's end, comes no nearer the end than
    /// its graze (so the end does not stop it), and then comes beside the wall 40 µm inside its contact radius, is met
    /// where it comes beside the wall, square to it: it does not go on sinking into the wall (2 mm by the move's end).
    /// </summary>
    [Fact]
    public void A_disc_that_grazes_a_walls_end_and_comes_beside_it_is_met_where_it_comes_beside()
    {
        // From 5 m before the end, 0.50021 m from the line, 40 m along it and 2 mm towards it: beside it 1/8 of the way.
        WallHit hit = Sweep(new Vector2(-5f, 0.50021f), new Vector2(40f, -2e-3f));
        hit.T.Should().BeApproximately(0.125f, 1e-6f, $"met where it comes beside the wall: {hit.T}, {hit.Normal}");
        hit.Normal.Should().Be(Vector2.UnitY, "the wall's own normal, towards the disc");
    }

    /// <summary>
    /// One that comes nearer the end than its graze before it comes beside is met on the end's circle, earlier, with
    /// the normal from the end to its centre there (turned towards the end, not the wall's).
    /// </summary>
    [Fact]
    public void A_disc_that_comes_nearer_a_walls_end_than_its_graze_is_met_on_the_ends_circle()
    {
        WallHit hit = Sweep(new Vector2(-5f, 0.50021f), new Vector2(40f, -0.02f));
        hit.T.Should().BeLessThan(0.125f, $"before it comes beside the wall: {hit.T}");
        hit.Normal.X.Should().BeLessThan(0f, $"from the end towards the centre, still short of the end: {hit.Normal}");
        Vector2 centre = new Vector2(-5f, 0.50021f) + (new Vector2(40f, -0.02f) * hit.T);
        Vector2.Distance(centre, A).Should().BeApproximately(0.5f, 1e-5f, $"at the contact radius from the end: {centre}");
    }

    /// <summary>A disc moving along the wall beyond its end, as near as its graze and no nearer, is not stopped.</summary>
    [Fact]
    public void A_disc_moving_past_a_walls_end_within_its_contact_radius_but_not_its_graze_is_free()
    {
        WallHit hit = Sweep(new Vector2(-5f, 0.49995f), new Vector2(40f, 0f));
        (hit.T, hit.Depth).Should().Be((1f, 0f), $"a graze: {hit.Normal}");
    }
}
