using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Body;

/// <summary>
/// A slide that meets a second wall after going a long way along the first: a room of Holtburg (floor at 94 m) with a
/// wall along y 100 from x 100 to 105 and a second from (105, 100) down to (110, 98), a concave bend of 22°. The
/// player's body (radius 0.48 m), step 0.6 m, centred frame.
/// </summary>
[Trait("Mutation", "BodySweep")]
public class BodySlideBendTests
{
    private const float Ground = 94f;
    private const uint Room = 0xA9B40100u;

    /// <summary>
    /// Walking (4, 2) m from (101, 99): met by the first wall a quarter of the way, the rest slides east along it (2.96
    /// m), meets the second wall 2.87 m on, and what is left of the slide (not of the move) goes on along the second.
    /// The end worked out in double: (104.9872, 99.4881); the move's own rest projected there would end at (104.9713,
    /// 99.4945).
    /// </summary>
    [Fact]
    public void A_slide_meeting_a_second_wall_far_along_the_first_goes_on_with_what_is_left_of_the_slide()
    {
        var room = new CellBuilder(Room).Floor(95f, 95f, 115f, 105f, Ground)
            .Physics(Wall(100f, 100f, 105f, 100f, Ground, Ground + 3f))
            .Physics(Wall(105f, 100f, 110f, 98f, Ground, Ground + 3f));
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground - 20f), [room.Build()]);
        ResolveResult r = engine.Resolve(engine.ToWorld(Holtburg, new Vector3(101f, 99f, Ground)), Room, new Vector3(4f, 2f, 0f), 0.6f, MovementOptions.Player);
        Vector3 local = engine.ToLandblockLocal(Holtburg, r.Position);
        local.X.Should().BeApproximately(104.9872f, 0.002f, $"slid along both walls: {r}");
        local.Y.Should().BeApproximately(99.4881f, 0.002f, $"slid along both walls: {r}");
        r.Outcome.Should().Be(ResolveOutcome.Slid);
    }
}
