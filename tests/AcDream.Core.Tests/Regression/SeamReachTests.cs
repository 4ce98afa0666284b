using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Regression;

/// <summary>
/// Walls of a neighbour's building cell that reach far over the seam are met wherever they stand, not only
/// when the move's own box crosses the seam: a body 5 m from the seam, moving 1 m at a time toward such a
/// wall 3.5 m into its landblock, stops at it (it walked through before, both frames).
/// </summary>
[Trait("Mutation", "ObjectQueries")]
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class SeamReachTests
{
    private const float GroundZ = 94f;

    [Theory]
    [InlineData("global", false)]
    [InlineData("centred", false)]
    [InlineData("global", true)]
    [InlineData("centred", true)]
    public void A_neighbours_wall_reaching_far_over_the_seam_stops_the_body(string frame, bool player)
    {
        const uint east = 0xAAB4FFFFu;
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), []);

        // The east neighbour's building cell: a wall along x = -3.5 (its frame: 3.5 m west of the seam, in
        // Holtburg) from y 90 to 110, 4 m high, no floor, and a door to the outdoors east of the seam.
        CellSurface cell = new CellBuilder(0xAAB40100u, new Vector3(0f, 100f, GroundZ))
            .Physics(Wall(-3.5f, -10f, -3.5f, 10f, 0f, 4f))
            .Portal(0xFFFF, new Vector3(3.5f, 1f, 1f), new(3f, 0.5f, 0f), new(4f, 0.5f, 0f), new(4f, 0.5f, 2f), new(3f, 0.5f, 2f)).Build();
        engine.AddLandblock(east, FlatTerrain(GroundZ, east), [cell]);

        MovementOptions options = player ? MovementOptions.Player : new MovementOptions { Body = MoverBody.Player };
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        var at = new ResolveResult(origin + new Vector3(187f, 100f, GroundZ), 0xA9B40000u, true);
        for (int i = 0; i < 6; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(1f, 0f, 0f), 0.6f, in options);
            (at.Position.X - origin.X).Should().BeLessThanOrEqualTo(188.5f - 0.479f, $"{frame}, move {i}: {at}");
        }

        at.Outcome.Should().Be(ResolveOutcome.Wall, $"{frame}: pressed against the wall: {at}");
    }

    /// <summary>
    /// A neighbour's reach into a landblock is looked up, not assumed: a neighbour replaced by one whose tree
    /// stands farther over the seam, and a corner neighbour whose tree stands over both seams, are met by a
    /// point and by a body walking up to them from inside the landblock (in 1 m moves that never cross the seam).
    /// </summary>
    [Theory]
    [InlineData("global", false)]
    [InlineData("centred", false)]
    [InlineData("global", true)]
    [InlineData("centred", true)]
    public void A_neighbour_reaching_farther_after_a_change_and_a_corner_neighbour_are_met(string frame, bool body)
    {
        const uint east = 0xAAB4FFFFu, northEast = 0xAAB5FFFFu;
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), []);
        var tree = ObjectKit.Tree(0.4f, 5f);
        ObjectSurface TreeAt(float x, float y) => new(tree.Setup, tree.Parts, ObjectKit.At(new Vector3(x, y, GroundZ), 0f), 0);
        engine.AddLandblock(east, FlatTerrain(GroundZ, east), [], [TreeAt(-1f, 100f)]);
        engine.AddLandblock(east, FlatTerrain(GroundZ, east), [], [TreeAt(-12f, 100f)]); // now 12 m over the seam, at Holtburg x 180
        engine.AddLandblock(northEast, FlatTerrain(GroundZ, northEast), [], [TreeAt(-5f, -5f)]); // at Holtburg (187, 187)

        MovementOptions options = body ? new MovementOptions { Body = MoverBody.Player } : default;
        float reach = body ? 0.4f + 0.48f : 0.4f; // the tree's radius, and the body's
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        foreach ((Vector2 start, float treeX) in new[] { (new Vector2(174.2f, 100f), 180f), (new Vector2(181.2f, 187f), 187f) })
        {
            var at = new ResolveResult(origin + new Vector3(start, GroundZ), 0xA9B40000u, true);
            for (int i = 0; i < 8; i++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(1f, 0f, 0f), 0.6f, in options);
                (at.Position.X - origin.X).Should().BeLessThanOrEqualTo(treeX - reach + 1e-3f, $"{frame}, from {start}, move {i}: {at}");
            }

            at.IsRefused.Should().BeTrue($"{frame}, from {start}: stopped at the tree: {at}");
        }
    }
}
