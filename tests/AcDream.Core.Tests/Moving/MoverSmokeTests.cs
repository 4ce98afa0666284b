using System.Numerics;
using AcDream.Core.Physics;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Moving;

/// <summary>A creature (a cylinder of the game's human size) on open ground: a wall to a body and a point, its rules.</summary>
[Trait("Mutation", "MoverRegistry")]
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class MoverSmokeTests(ITestOutputHelper output)
{
    internal const uint Landblock = 0x7A3BFFFF;
    internal const uint Outdoor = 0x7A3B0000 | 0x001C;
    internal const float Ground = 50f;
    internal static readonly Vector2 Axis = new(96f, 96f);

    /// <summary>Flat ground at <see cref="Ground"/> in <see cref="Landblock"/>, in the frame centred on it or the global one.</summary>
    internal static PhysicsEngine Field(string frame = "centred")
    {
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Landblock);
        engine.AddLandblock(Landblock, TestData.FlatTerrain(Ground, Landblock), []);
        return engine;
    }

    internal static Vector3 World(PhysicsEngine engine, Vector2 local) => engine.ToWorld(Landblock, new Vector3(local, Ground));

    [Fact]
    public void A_body_walking_at_a_creature_stops_at_their_radii_and_a_point_is_refused()
    {
        PhysicsEngine engine = Field();
        engine.Movers.Add(7, MoverShape.Cylinder(0.48f, 1.835f), World(engine, Axis), Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();

        var at = new ResolveResult(World(engine, Axis - new Vector2(3f, 0f)), Outdoor, true);
        for (int i = 0; i < 60; i++)
        {
            at = engine.Resolve(at.Position, at.CellId, new Vector3(0.1f, 0f, 0f), 0.6f, MovementOptions.Player, 0u, [], out _, out MoveReport report);
            if (at.IsRefused || at.Outcome == ResolveOutcome.Slid)
            {
                report.Wall.Kind.Should().Be(SurfaceKind.Mover, $"{at} {report}");
                report.Wall.Id.Should().Be(7u);
            }
        }

        float gap = Vector2.Distance(new Vector2(at.Position.X, at.Position.Y), new Vector2(World(engine, Axis).X, World(engine, Axis).Y));
        output.WriteLine($"end {at}, centre distance {gap}");
        gap.Should().BeInRange(0.96f - 0.001f, 0.96f + 0.01f, $"{at}");

        ResolveResult point = engine.Resolve(World(engine, Axis - new Vector2(2f, 0f)), Outdoor, new Vector3(4f, 0f, 0f), 0.6f);
        point.Outcome.Should().Be(ResolveOutcome.Wall, $"{point}");
        point.Position.Should().Be(World(engine, Axis - new Vector2(2f, 0f)));
    }

    [Fact]
    public void Its_own_id_is_skipped_and_an_ethereal_one_is_only_touched()
    {
        PhysicsEngine engine = Field();
        engine.Movers.Add(7, MoverShape.Cylinder(0.48f, 1.835f), World(engine, Axis), Outdoor, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        Vector3 start = World(engine, Axis - new Vector2(1.5f, 0f));
        var across = new Vector3(3f, 0f, 0f);
        engine.Resolve(start, Outdoor, across, 0.6f, MovementOptions.Player, 7u).Outcome.Should().Be(ResolveOutcome.Moved, "a mover does not meet itself");
        engine.Resolve(start, Outdoor, across, 0.6f, MovementOptions.Player).Outcome.Should().NotBe(ResolveOutcome.Moved);

        engine.Movers.SetState(7, MoverState.Creature with { Physics = PhysicsStateFlags.Ethereal });
        engine.Movers.Commit();
        Span<uint> touched = stackalloc uint[4];
        ResolveResult r = engine.Resolve(start, Outdoor, across, 0.6f, MovementOptions.Player, 0u, touched, out int count, out _);
        r.Outcome.Should().Be(ResolveOutcome.Moved, $"{r}");
        count.Should().Be(1);
        touched[0].Should().Be(7u);

        engine.Movers.SetState(7, MoverState.Creature with { Physics = PhysicsStateFlags.Ethereal | PhysicsStateFlags.IgnoreCollisions });
        engine.Movers.Commit();
        engine.Resolve(start, Outdoor, across, 0.6f, MovementOptions.Player, 0u, touched, out count, out _).Outcome.Should().Be(ResolveOutcome.Moved);
        count.Should().Be(0, "both Ethereal and IgnoreCollisions: not met at all");
    }
}
