using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// Where the body meets walls that are not plain vertical rectangles: a wall leaning away is met where it
/// rises through the step height (what is lower is a step), a wall leaning over the body where it comes down
/// to the body's height (what is higher is above its head), and a gable wall of a neighbour's building across
/// the seam where it stands. Both world frames; the player's body (radius 0.48 m, height 1.2 m here), step 0.6 m.
/// </summary>
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class BodyWallTests
{
    private const float Step = 0.6f;
    private const float GroundZ = 94f;
    private static readonly MoverBody Body = new(0.48f, 1.2f);

    public static TheoryData<string> Frames => new() { "global", "centred" };

    private static PhysicsEngine Engine(string frame) => frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);

    /// <summary>
    /// A room (x 100..120, y 100..104) with one leaning wall across it, from (<paramref name="bottomX"/>, z 0) up to
    /// (<paramref name="topX"/>, z <paramref name="top"/>) above the floor: a body 2 m west of it walks 3 m east.
    /// Returns the centre's X where it stops, landblock-local.
    /// </summary>
    private static ResolveResult WalkInto(string frame, float bottomX, float topX, float top)
    {
        CellSurface room = new CellBuilder(0xA9B40100u).Floor(100f, 100f, 120f, 104f, GroundZ)
            .Physics(new(bottomX, 100f, GroundZ), new(bottomX, 104f, GroundZ), new(topX, 104f, GroundZ + top), new(topX, 100f, GroundZ + top))
            .Build();
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [room]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        ResolveResult r = engine.Resolve(origin + new Vector3(108f, 102f, GroundZ), 0xA9B40100u, new Vector3(3f, 0f, 0f), Step, new MovementOptions { Body = Body });
        return r with { Position = r.Position - origin };
    }

    /// <summary>
    /// Asserts a body stopped at X <paramref name="x"/> (landblock-local) keeps its radius from a wall at
    /// <paramref name="wallX"/>: no nearer, and no farther than its skin and the rounding of the world frame
    /// (three float spacings at its largest world coordinate, Holtburg's Y: about 12 mm in the global frame).
    /// </summary>
    private static void AtRadius(float x, float wallX, string frame, ResolveResult r, string what)
    {
        float largest = frame == "global" ? (0xB4 * 192f) + 200f : 200f;
        float slack = (3f * (MathF.BitIncrement(largest) - largest)) + 1e-4f;
        (wallX - x).Should().BeInRange(Body.Radius - 1e-4f, Body.Radius + slack, $"{frame}: {what}: {r}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_wall_leaning_away_is_met_where_it_rises_through_the_step_height(string frame)
    {
        // From x 110 at the floor to x 111 two metres up: at the step height (0.6 m) it stands at x 110.3.
        ResolveResult r = WalkInto(frame, 110f, 111f, 2f);
        (r.Outcome, r.SurfaceNormal.X).Should().Be((ResolveOutcome.Slid, -1f), $"{frame}: moved up to the wall, facing it: {r}");
        AtRadius(r.Position.X, 110.3f, frame, r, "stopped at its radius from the wall at the step height, not at its foot");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_wall_leaning_over_the_body_is_met_where_it_comes_down_to_the_bodys_height(string frame)
    {
        // From x 111 at the floor to x 110 2.5 m up: at the body's height (1.2 m) it stands at x 110.52.
        ResolveResult r = WalkInto(frame, 111f, 110f, 2.5f);
        (r.Outcome, r.SurfaceNormal.X).Should().Be((ResolveOutcome.Slid, -1f), $"{frame}: moved up to the wall, facing it: {r}");
        AtRadius(r.Position.X, 110.52f, frame, r, "stopped at its radius from the wall at its head's height, not at the wall's top");
    }

    /// <summary>
    /// The east neighbour's cottage has a gable wall (a pentagon: not a rectangle, so cut to the body's band)
    /// 1 m east of the seam; a body 3 m west of the seam walking 5 m east stops at it.
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void A_neighbours_gable_wall_across_the_seam_stops_the_body(string frame)
    {
        const uint east = 0xAAB4FFFFu;
        CellSurface cottage = new CellBuilder(0xAAB40100u).Floor(1f, 96f, 7f, 104f, GroundZ)
            .Physics(new(1f, 96f, GroundZ), new(1f, 104f, GroundZ), new(1f, 104f, GroundZ + 3f), new(1f, 100f, GroundZ + 4f), new(1f, 96f, GroundZ + 3f))
            .Portal(0xFFFF, new Vector3(4f, 100f, GroundZ + 1f), Wall(3f, 104f, 5f, 104f, GroundZ, GroundZ + 2.5f)).Build();
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), []);
        engine.AddLandblock(east, FlatTerrain(GroundZ, east), [cottage]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);

        ResolveResult r = engine.Resolve(origin + new Vector3(189f, 100f, GroundZ), 0xA9B40000u, new Vector3(5f, 0f, 0f), Step, new MovementOptions { Body = Body });
        (r.Outcome, r.SurfaceNormal.X).Should().Be((ResolveOutcome.Slid, -1f), $"{frame}: moved up to the wall, facing it: {r}");
        AtRadius(r.Position.X - origin.X, 193f, frame, r, "at its radius from the gable, 1 m past the seam");
    }
    /// <summary>
    /// A body its caller placed 5 cm into a long wall moves along it where it is: such an overlap is not the
    /// rounding the body's skin absorbs, so it is left alone (not pushed out to the radius, not pulled deeper).
    /// </summary>
    [Theory]
    [MemberData(nameof(Frames))]
    public void A_body_placed_deep_in_a_wall_moves_along_it_where_it_is(string frame)
    {
        CellSurface room = new CellBuilder(0xA9B40100u).Floor(100f, 100f, 120f, 104f, GroundZ).Physics(Wall(100f, 104f, 120f, 104f, GroundZ, GroundZ + 3f)).Build();
        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [room]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        Vector3 start = origin + new Vector3(105f, 104f - Body.Radius + 0.05f, GroundZ);

        ResolveResult r = engine.Resolve(start, 0xA9B40100u, new Vector3(2f, 0f, 0f), Step, new MovementOptions { Body = Body });
        r.Outcome.Should().Be(ResolveOutcome.Moved, $"{frame}: {r}");
        (r.Position.X - start.X).Should().BeApproximately(2f, 0.01f, $"{frame}: the whole move along the wall: {r}");
        r.Position.Y.Should().Be(start.Y, $"{frame}: as deep as it was, neither pushed out nor pulled in: {r}");
    }
    /// <summary>
    /// A wall bent a little more at each of its corners (a fan of <paramref name="walls"/> 3 m pieces falling away
    /// at 10°, 20°, 30°, ... across the body's way), the last piece 10 m long: a body walking 15 m into the first slides
    /// along each piece in turn, one contact each. After <see cref="PhysicsConstants.MaxBodyContacts"/> contacts a
    /// move stops where the last one touched; with fewer pieces it slides on along the last to the move's end.
    /// </summary>
    [Theory]
    [InlineData("global", 3)]
    [InlineData("centred", 3)]
    [InlineData("global", 4)]
    [InlineData("centred", 4)]
    public void A_body_slides_through_as_many_contacts_as_the_limit_and_stops_at_the_last(string frame, int walls)
    {
        var corners = new List<Vector2> { new(100f, 106f) };
        for (int i = 1; i <= walls; i++)
        {
            float angle = i * 10f * MathF.PI / 180f, length = i == walls ? 10f : 3f;
            corners.Add(corners[^1] + (new Vector2(MathF.Cos(angle), -MathF.Sin(angle)) * length));
        }

        var room = new CellBuilder(0xA9B40100u).Floor(95f, 80f, 130f, 110f, GroundZ);
        for (int i = 0; i < walls; i++)
        {
            room.Physics(Wall(corners[i].X, corners[i].Y, corners[i + 1].X, corners[i + 1].Y, GroundZ, GroundZ + 3f));
        }

        PhysicsEngine engine = Engine(frame);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [room.Build()]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        ResolveResult r = engine.Resolve(origin + new Vector3(100.5f, 105.4f, GroundZ), 0xA9B40100u, new Vector3(15f, 0f, 0f), Step, new MovementOptions { Body = Body });
        var end = new Vector2(r.Position.X - origin.X, r.Position.Y - origin.Y);
        double[] gaps = [.. Enumerable.Range(0, walls).Select(i => Distance(end, corners[i], corners[i + 1]))];
        string what = $"{frame}, {walls} pieces: {r}; gaps to the pieces {string.Join(", ", gaps.Select(g => g.ToString("F4")))}";
        r.Outcome.Should().Be(ResolveOutcome.Slid, what);
        gaps.Min().Should().BeGreaterThan(Body.Radius - 1e-3, $"never into a piece: {what}");
        if (walls == PhysicsConstants.MaxBodyContacts)
        {
            gaps[^2].Should().BeLessThan(Body.Radius + 0.02, $"stopped where the last piece touched, at the corner it makes with the one before: {what}");
            gaps[^1].Should().BeLessThan(Body.Radius + 0.02, what);
        }
        else
        {
            gaps[^1].Should().BeLessThan(Body.Radius + 0.02, $"along the last piece: {what}");
            gaps[^2].Should().BeGreaterThan(1.0, $"slid on along the last piece, far from the corner: {what}");
        }
    }

    /// <summary>Distance from <paramref name="p"/> to the segment <paramref name="a"/>–<paramref name="b"/>, in doubles.</summary>
    private static double Distance(Vector2 p, Vector2 a, Vector2 b)
    {
        double abX = (double)b.X - a.X, abY = (double)b.Y - a.Y, apX = (double)p.X - a.X, apY = (double)p.Y - a.Y;
        double u = Math.Clamp(((apX * abX) + (apY * abY)) / ((abX * abX) + (abY * abY)), 0, 1);
        double dx = apX - (u * abX), dy = apY - (u * abY);
        return Math.Sqrt((dx * dx) + (dy * dy));
    }
}
