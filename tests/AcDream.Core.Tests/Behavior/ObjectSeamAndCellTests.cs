using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;

namespace AcDream.Core.Tests.Behavior;

/// <summary>Objects at a landblock seam and inside a cell.</summary>
[Trait("Mutation", "ObjectQueries")]
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class ObjectSeamAndCellTests
{
    private const uint West = 0x5050FFFF;
    private const uint EastLb = 0x5150FFFF;

    /// <summary>A wall 4 m long (along y), 3 m high, one polygon facing +x (object-local x 0).</summary>
    private static GfxObj Fence() => ObjectKit.Gfx(0x01000321, new Vector3[] { new(0, -2, 0), new(0, 2, 0), new(0, 2, 3), new(0, -2, 3) });

    /// <summary>A 2 m square platform 0.4 m high (top and four sides).</summary>
    private static GfxObj Platform() => ObjectKit.Gfx(
        0x01000322,
        [new(-1, -1, 0.4f), new(1, -1, 0.4f), new(1, 1, 0.4f), new(-1, 1, 0.4f)],
        [new(-1, -1, 0), new(1, -1, 0), new(1, -1, 0.4f), new(-1, -1, 0.4f)],
        [new(1, -1, 0), new(1, 1, 0), new(1, 1, 0.4f), new(1, -1, 0.4f)],
        [new(1, 1, 0), new(-1, 1, 0), new(-1, 1, 0.4f), new(1, 1, 0.4f)],
        [new(-1, 1, 0), new(-1, -1, 0), new(-1, -1, 0.4f), new(-1, 1, 0.4f)]);

    [Theory]
    [InlineData("point")]
    [InlineData("body")]
    public void A_wall_near_the_seam_stops_a_mover_coming_from_the_neighbour(string mover)
    {
        MovementOptions options = mover == "point" ? MovementOptions.Literal : new MovementOptions { Body = MoverBody.Player };
        var engine = new PhysicsEngine(West);
        engine.AddLandblock(West, TestData.FlatTerrain(20f, West), [], [new ObjectSurface(Fence(), ObjectKit.At(new Vector3(191.7f, 100f, 20f), 0f), 0)]);
        engine.AddLandblock(EastLb, TestData.FlatTerrain(20f, EastLb), []);
        var at = new ResolveResult(new Vector3(193f, 100f, 20f), 0x51500000, true);
        for (int i = 0; i < 20; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(-0.1f, 0f, 0f), 0.6f, options);
            at.Position.X.Should().BeGreaterThan(191.7f + (mover == "body" ? 0.479f : 0f), $"{mover}, move {i}: {at}");
        }
    }

    [Theory]
    [InlineData("point")]
    [InlineData("body")]
    public void A_wall_overhanging_the_seam_stops_a_mover_in_the_neighbour(string mover)
    {
        MovementOptions options = mover == "point" ? MovementOptions.Literal : new MovementOptions { Body = MoverBody.Player };
        var engine = new PhysicsEngine(West);
        // Placed in the west landblock at local x 193: the fence stands 1 m into the east one.
        engine.AddLandblock(West, TestData.FlatTerrain(20f, West), [], [new ObjectSurface(Fence(), ObjectKit.At(new Vector3(193f, 100f, 20f), 0f), 0)]);
        engine.AddLandblock(EastLb, TestData.FlatTerrain(20f, EastLb), []);
        var at = new ResolveResult(new Vector3(195f, 100f, 20f), 0x51500000, true);
        for (int i = 0; i < 30; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(-0.1f, 0f, 0f), 0.6f, options);
            at.Position.X.Should().BeGreaterThan(193f + (mover == "body" ? 0.479f : 0f), $"{mover}, move {i}: {at}");
        }
    }

    [Theory]
    [InlineData("point", true)]
    [InlineData("point", false)]
    [InlineData("body", true)]
    [InlineData("body", false)]
    public void A_wall_overhanging_the_seam_follows_its_landblock_in_and_out(string mover, bool neighbourFirst)
    {
        MovementOptions options = mover == "point" ? MovementOptions.Literal : new MovementOptions { Body = MoverBody.Player };
        var engine = new PhysicsEngine();
        var fence = new ObjectSurface(Fence(), ObjectKit.At(new Vector3(193f, 100f, 20f), 0f), 0);
        if (neighbourFirst)
        {
            engine.AddLandblock(EastLb, TestData.FlatTerrain(20f, EastLb), []);
            engine.AddLandblock(West, TestData.FlatTerrain(20f, West), [], [fence]);
        }
        else
        {
            engine.AddLandblock(West, TestData.FlatTerrain(20f, West), [], [fence]);
            engine.AddLandblock(EastLb, TestData.FlatTerrain(20f, EastLb), []);
        }

        // The east landblock's local x 3 in the global frame; the fence stands at its local x 1.
        Vector3 start = engine.ToWorld(EastLb, new Vector3(3f, 100f, 20f));
        ResolveResult Walk()
        {
            var at = new ResolveResult(start, 0x51500000, true);
            for (int i = 0; i < 30; i++)
            {
                at = engine.Resolve(at.Position, at.CellId, new Vector3(-0.1f, 0f, 0f), 0.6f, options);
            }

            return at;
        }

        float fenceX = engine.ToWorld(EastLb, new Vector3(1f, 0f, 0f)).X;
        ResolveResult stopped = Walk();
        stopped.Position.X.Should().BeGreaterThan(fenceX + (mover == "body" ? 0.479f : 0f), $"{mover}: the fence stops it: {stopped}");

        engine.RemoveLandblock(West);
        ResolveResult free = Walk();
        free.Position.X.Should().BeLessThan(fenceX, $"{mover}: with the west landblock gone, so is its fence (the mover walks on to the seam): {free}");
        engine.AddLandblock(West, TestData.FlatTerrain(20f, West), [], [fence]);
        Walk().Should().Be(stopped, "the fence is back with its landblock");
    }

    [Theory]
    [InlineData("point")]
    [InlineData("Player")]
    public void A_platform_in_a_room_is_stepped_onto_and_its_floor_found(string mover)
    {
        MovementOptions options = mover == "point" ? MovementOptions.Literal : MovementOptions.Player;
        List<CellSurface> cells = HoltburgCells.Surfaces();
        CellSurface room = cells.Single(c => c.CellId == 0xA9B40143);
        var centre = new Vector2(139.4f, 6.5f);
        room.SampleFloorZ(centre.X, centre.Y, 94f).Should().Be(94f, "the room's floor is under the platform");
        var engine = new PhysicsEngine(TestData.Holtburg);
        var platform = new ObjectSurface(Platform(), ObjectKit.At(new Vector3(centre, 94f), 0.2f), room.CellId);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), cells, [platform, .. RealObjects.HoltburgBuildings()]);
        engine.TryGetGround(new Vector3(centre, 94f), room.CellId, 0.6f, out float z, out _, out uint id).Should().BeTrue();
        (z, id).Should().Be((94.4f, 0x01000322u));
        engine.TryGetGround(new Vector3(centre, 94f), room.CellId, 0.3f, out z, out _, out id).Should().BeTrue();
        (z, id).Should().Be((94f, 0u), "a step of 0.3 m does not reach the platform's top");

        var at = new ResolveResult(new Vector3(centre.X - 2.5f, centre.Y, 94f), room.CellId, true);
        at = engine.Resolve(at.Position, at.CellId, Vector3.Zero, 0.6f, options);
        at.Position.Z.Should().Be(94f, $"{at}");
        for (int i = 0; i < 25; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0.1f, 0f, 0f), 0.6f, options);
        }

        at.CellId.Should().Be(room.CellId, $"{at}");
        at.Position.Z.Should().BeApproximately(94.4f, 1e-4f, $"{mover} on the platform: {at}");

        // With a step of 0.3 m the platform's side is a wall: refused (point) or stopped (body).
        at = new ResolveResult(new Vector3(centre.X - 2.5f, centre.Y, 94f), room.CellId, true);
        for (int i = 0; i < 25; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0.1f, 0f, 0f), 0.3f, options);
            at.Position.Z.Should().Be(94f, $"{mover}, step 0.3, move {i}: {at}");
        }
    }

    [Theory]
    [InlineData("point")]
    [InlineData("body")]
    public void A_tree_in_a_room_stops_the_point_and_keeps_the_body_off(string mover)
    {
        MovementOptions options = mover == "point" ? MovementOptions.Literal : new MovementOptions { Body = MoverBody.Player };
        List<CellSurface> cells = HoltburgCells.Surfaces();
        var axis = new Vector2(139.4f, 6.5f);
        (Setup tree, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree(0.3f, 2f);
        var engine = new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(94f), cells, [new ObjectSurface(tree, parts, ObjectKit.At(new Vector3(axis, 94f), 0f), 0xA9B40143)]);
        foreach (float offset in new[] { 0f, 0.2f, -0.5f })
        {
            var at = new ResolveResult(new Vector3(axis.X - 2f, axis.Y + offset, 94f), 0xA9B40143, true);
            bool stopped = false;
            for (int i = 0; i < 25; i++)
            {
                ResolveResult r = engine.Resolve(at.Position, at.CellId, new Vector3(0.1f, 0f, 0f), 0.6f, options);
                float d = Vector2.Distance(new Vector2(r.Position.X, r.Position.Y), axis);
                d.Should().BeGreaterThan((mover == "point" ? 0.3f : 0.78f) - 0.001f, $"{mover}, offset {offset}, move {i}: {at} → {r}");
                if (mover == "point" && r.IsRefused)
                {
                    r.Outcome.Should().Be(ResolveOutcome.Wall, $"{r}");
                    stopped = true;
                }

                r.CellId.Should().Be(0xA9B40143u, $"{r}");
                at = r;
            }

            if (mover == "point")
            {
                stopped.Should().Be(MathF.Abs(offset) < 0.3f, $"offset {offset}: {at}");
            }
        }
    }

    [Theory]
    [InlineData("point")]
    [InlineData("Player")]
    public void The_staircase_side_is_a_wall_where_it_is_higher_than_the_step(string mover)
    {
        MovementOptions options = mover == "point" ? MovementOptions.Literal : MovementOptions.Player;
        var engine = new PhysicsEngine(0xF682FFFF);
        engine.AddLandblock(0xF682FFFF, TestData.FlatTerrain(58.815f, 0xF682FFFF), [], RealObjects.Staircase());
        // The pieces are slabs 0.6 m thick: at y 78 piece 6 spans z 60.9…61.5, above a player's head (60.65),
        // so a mover walks under it.
        var under = new ResolveResult(new Vector3(134f, 78f, 58.815f), 0xF6820000, true);
        for (int i = 0; i < 30; i++)
        {
            under = engine.Resolve(under.Position, under.CellId, new Vector3(-0.1f, 0f, 0f), 0.6f, options);
        }

        // (The body's top does touch the underside of piece 5 at y < 77.99, which turns it a little north.)
        under.Position.X.Should().BeLessThan(131.75f, $"{mover} walked under the top of the staircase: {under}");
        under.Position.Z.Should().Be(58.815f, $"{under}");

        // At y 76.2 piece 2 spans z 59.38…59.98 (x 131.25…132.75): its side crosses the feet + step (59.415) and the body.
        var at = new ResolveResult(new Vector3(134f, 76.2f, 58.815f), 0xF6820000, true);
        for (int i = 0; i < 20; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(-0.1f, 0f, 0f), 0.6f, options);
            at.Position.X.Should().BeGreaterThan(132.75f + (mover == "point" ? 0f : 0.479f), $"{mover}, move {i}: {at}");
            at.Position.Z.Should().Be(58.815f, $"{at}");
        }

        // Beside the first tread (0.2 m to 0.6 m up): stepped onto from the side.
        at = new ResolveResult(new Vector3(134f, 75.1f, 58.815f), 0xF6820000, true);
        for (int i = 0; i < 20; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(-0.1f, 0f, 0f), 0.6f, options);
        }

        at.Position.X.Should().BeLessThan(132.75f, $"{mover}: on the first tread: {at}");
        at.Position.Z.Should().BeApproximately(59.015f + (0.8f * (at.Position.Y - 74.995f)), 1e-4f, $"on the tread's plane: {at}");
    }
}
