using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Behavior;

/// <summary>A tree: a Setup whose one part has no polygons and whose cylinder (radius 0.4, height 5) is its trunk.</summary>
[Trait("Mutation", "ObjectQueries")]
public class CylinderTests(ITestOutputHelper output)
{
    private const uint Landblock = 0x7A3BFFFF;
    private const uint Outdoor = 0x7A3B0000;
    private const float Ground = 50f;
    private const float Reach = 0.48f + 0.4f;
    private static readonly Vector2 Axis = new(96f, 96f);

    private static PhysicsEngine Forest()
    {
        (var setup, var parts) = ObjectKit.Tree();
        var engine = new PhysicsEngine(Landblock);
        var tree = new ObjectSurface(setup, parts, ObjectKit.At(new Vector3(Axis, Ground), 0.7f), 0);
        tree.GetFloorTriangles().Should().BeEmpty();
        tree.GetWalls().Should().ContainSingle().Which.Radius.Should().Be(0.4f);
        engine.AddLandblock(Landblock, TestData.FlatTerrain(Ground, Landblock), [], [tree]);
        return engine;
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(90f)]
    [InlineData(200f)]
    [InlineData(315f)]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void A_point_is_refused_entering_the_trunk(float direction)
    {
        PhysicsEngine engine = Forest();
        float a = direction * MathF.PI / 180f;
        var dir = new Vector2(MathF.Cos(a), MathF.Sin(a));
        var at = new ResolveResult(new Vector3(Axis - (dir * 2f), Ground), Outdoor, true);
        ResolveResult? refusal = null;
        for (int i = 0; i < 40; i++)
        {
            ResolveResult r = engine.Resolve(at.Position, at.CellId, new Vector3(dir * 0.1f, 0f), 0.6f);
            Vector2.Distance(new Vector2(r.Position.X, r.Position.Y), Axis).Should().BeGreaterThan(0.4f, $"move {i}: {r}");
            if (r.IsRefused)
            {
                refusal ??= r;
            }

            at = r;
        }

        refusal.Should().NotBeNull("the trunk stopped it");
        refusal!.Value.Outcome.Should().Be(ResolveOutcome.Wall, $"{refusal}");
        Vector3.Distance(refusal.Value.SurfaceNormal, new Vector3(-dir, 0f)).Should().BeLessThan(0.05f, $"the trunk's normal at the hit faces the mover: {refusal}");

        // One long move through the trunk is refused too, and one beside it (0.45 m from the axis) is not.
        engine.Resolve(new Vector3(Axis - (dir * 3f), Ground), Outdoor, new Vector3(dir * 6f, 0f), 0.6f).Outcome.Should().Be(ResolveOutcome.Wall);
        var beside = new Vector2(-dir.Y, dir.X) * 0.45f;
        ResolveResult past = engine.Resolve(new Vector3(Axis - (dir * 3f) + beside, Ground), Outdoor, new Vector3(dir * 6f, 0f), 0.6f);
        past.Outcome.Should().Be(ResolveOutcome.Moved, $"{past}");

        // A mover whose step clears the trunk's top (5 m) is not stopped: the trunk is a wall of its height.
        engine.Resolve(new Vector3(Axis - (dir * 3f), Ground + 4.5f), Outdoor, new Vector3(dir * 6f, 0f), 0.6f).Outcome.Should().NotBe(ResolveOutcome.Wall);
    }

    public static TheoryData<string, float> Speeds() => new()
    {
        { "body", 1f }, { "body", 5f }, { "body", 20f }, { "body", 50f },
        { "Player", 1f }, { "Player", 5f }, { "Player", 20f }, { "Player", 50f },
    };

    [Theory]
    [MemberData(nameof(Speeds))]
    public void A_body_keeps_its_radius_plus_the_trunks_from_the_axis_and_slides_round_it(string mover, float speed)
    {
        PhysicsEngine engine = Forest();
        MovementOptions options = mover == "body" ? new MovementOptions { Body = MoverBody.Player } : MovementOptions.Player;
        float worst = float.MaxValue;
        int slid = 0, passed = 0, runs = 0;
        foreach (float offset in new[] { 0f, 0.05f, 0.2f, 0.5f, 0.8f, -0.3f })
        {
            foreach (float direction in new[] { 0f, 37f, 150f, 260f })
            {
                float a = direction * MathF.PI / 180f;
                var dir = new Vector2(MathF.Cos(a), MathF.Sin(a));
                var side = new Vector2(-dir.Y, dir.X);
                var at = new ResolveResult(new Vector3(Axis - (dir * 8f) + (side * offset), Ground), Outdoor, true);
                float step = speed * 0.1f; // 10 Hz
                int calls = (int)MathF.Ceiling(16f / step) * 3;
                for (int i = 0; i < calls; i++)
                {
                    ResolveResult r = engine.Resolve(at.Position, at.CellId, new Vector3(dir * step, 0f), 0.6f, options);
                    float d = Vector2.Distance(new Vector2(r.Position.X, r.Position.Y), Axis);
                    worst = MathF.Min(worst, d);
                    d.Should().BeGreaterThan(Reach - 0.001f, $"{mover} {speed} m/s, offset {offset}, direction {direction}, call {i}: {at} → {r}");
                    r.Position.Z.Should().Be(Ground, $"{r}");
                    slid += r.Outcome == ResolveOutcome.Slid ? 1 : 0;
                    at = r;
                }

                runs++;
                float along = Vector2.Dot(new Vector2(at.Position.X, at.Position.Y) - Axis, dir);
                if (offset != 0f)
                {
                    along.Should().BeGreaterThan(Reach, $"{mover} {speed} m/s, offset {offset}, direction {direction}: slid round the trunk and went on: {at}");
                    passed++;
                }
                else if (direction == 0f)
                {
                    // Exactly head on (axis-aligned, no rounding off the line): nothing turns it either way.
                    along.Should().BeLessThan(0f, $"head on it stays in front: {at}");
                }
            }
        }

        output.WriteLine($"{mover} at {speed} m/s: {runs} runs, {passed} past the trunk, {slid} slides; closest centre to the axis {worst:R} (reach {Reach:R}, overlap {Reach - worst:E2} m)");
        slid.Should().BeGreaterThan(0);
    }

    [Fact]
    [Trait("Mutation", "WallSet")]
    [Trait("Mutation", "BodySweep")]
    public void Random_moves_round_the_trunk_never_overlap_it_by_more_than_a_millimetre()
    {
        PhysicsEngine engine = Forest();
        var random = new Random(17);
        float worst = float.MaxValue;
        foreach (MovementOptions options in new[] { new MovementOptions { Body = MoverBody.Player }, MovementOptions.Player })
        {
            for (int walk = 0; walk < 60; walk++)
            {
                float a = (float)(random.NextDouble() * 2 * Math.PI);
                var at = new ResolveResult(new Vector3(Axis + (new Vector2(MathF.Cos(a), MathF.Sin(a)) * (Reach + 0.01f + (float)(random.NextDouble() * 3))), Ground), Outdoor, true);
                for (int m = 0; m < 30; m++)
                {
                    Vector2 toward = Vector2.Normalize(Axis - new Vector2(at.Position.X, at.Position.Y));
                    float turn = (float)((random.NextDouble() - 0.5) * 2.5);
                    var dir = new Vector2((toward.X * MathF.Cos(turn)) - (toward.Y * MathF.Sin(turn)), (toward.X * MathF.Sin(turn)) + (toward.Y * MathF.Cos(turn)));
                    float step = (float)(random.NextDouble() * 5); // up to 50 m/s at 10 Hz
                    ResolveResult r = engine.Resolve(at.Position, at.CellId, new Vector3(dir * step, 0f), 0.6f, options);
                    float d = Vector2.Distance(new Vector2(r.Position.X, r.Position.Y), Axis);
                    worst = MathF.Min(worst, d);
                    d.Should().BeGreaterThan(Reach - 0.001f, $"walk {walk}, move {m}: {at} → {r}");
                    at = r;
                }
            }
        }

        output.WriteLine($"closest centre to the axis {worst:R}, overlap {Reach - worst:E2} m");
    }
}
