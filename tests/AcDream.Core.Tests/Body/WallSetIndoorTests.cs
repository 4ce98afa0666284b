using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Body;

/// <summary>
/// Walls gathered for a body inside a cell (<c>WallSet</c>): a rat lower than the step standing in a room, and a face
/// too steep to stand on (normal Z 0.5) in a room under a fall. A room of Holtburg (x 100..120, y 100..104, floor at 94 m)
/// with no walls; the player's body (radius 0.48 m, 1.835 m), step 0.6 m.
/// </summary>
[Trait("Mutation", "WallSet")]
public class WallSetIndoorTests
{
    private const float Ground = 94f;
    private const uint Room = 0xA9B40100u;

    public static TheoryData<string> Frames => new() { "global", "centred" };

    private static PhysicsEngine InRoom(string frame, Action<CellBuilder> more)
    {
        var builder = new CellBuilder(Room).Floor(100f, 100f, 120f, 104f, Ground);
        more(builder);
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(Ground - 20f), [builder.Build()]);
        return engine;
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_rat_lower_than_the_step_in_a_room_stops_the_body_at_their_radii(string frame)
    {
        PhysicsEngine engine = InRoom(frame, _ => { });
        Vector3 rat = engine.ToWorld(Holtburg, new Vector3(110f, 102f, Ground));
        engine.Movers.Add(4, MoverShape.Cylinder(0.3f, 0.5f), rat, Room, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        ResolveResult r = engine.Resolve(engine.ToWorld(Holtburg, new Vector3(107f, 102f, Ground)), Room, new Vector3(5f, 0f, 0f), 0.6f, MovementOptions.Player);
        float apart = rat.X - r.Position.X;
        apart.Should().BeInRange(0.78f - 0.001f, 0.79f, $"{frame}: stopped at the rat: {r}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_fall_onto_a_steep_face_in_a_room_is_held_on_it(string frame)
    {
        // The face rises from (104..108, 101) at 96 m to (104..108, 102) at 97.73 m; the body falls 3 m over its middle.
        float rise = MathF.Sqrt(3f);
        PhysicsEngine engine = InRoom(frame, b => b.Physics(new(104f, 101f, Ground + 2f), new(108f, 101f, Ground + 2f), new(108f, 102f, Ground + 2f + rise), new(104f, 102f, Ground + 2f + rise)));
        ResolveResult r = engine.Resolve(engine.ToWorld(Holtburg, new Vector3(106f, 101.5f, Ground + 5f)), Room, new Vector3(0f, 0f, -3f), 0.6f, MovementOptions.Player);
        Vector3 local = engine.ToLandblockLocal(Holtburg, r.Position);
        double face = Ground + 2.0 + (rise * (Math.Min(102.0, local.Y + 0.48) - 101.0)); // its highest point under the disc
        (local.Z - face).Should().BeGreaterThan(-1e-3, $"{frame}: never through the face: {r}");
        (r.Outcome, r.IsOnGround).Should().Be((ResolveOutcome.Slid, false), $"{frame}: landed on it, too steep to stand on: {r}");
        r.SurfaceNormal.Z.Should().BeApproximately(0.5f, 1e-3f, "the face's normal");
        local.Z.Should().BeGreaterThan(Ground + 2f + 0.5f, $"{frame}: held well above its foot: {r}");
    }
}
