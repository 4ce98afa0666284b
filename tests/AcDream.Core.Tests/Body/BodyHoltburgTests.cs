using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Body;

/// <summary>The body on the real Holtburg cells (flat terrain at the cottages' floor height, 94 m).</summary>
public class BodyHoltburgTests
{
    private const float GroundZ = 94f;
    private const float Step = BodyDoorways.Step;

    public static TheoryData<string> LowDoorways() => [.. BodyDoorways.Low.Select(d => d.Name)];

    private static Doorway Named(string name) => BodyDoorways.Real.Concat(BodyDoorways.Low).Single(d => d.Name == name);

    private static readonly Lazy<ReferenceBody> Walls = new(() => ReferenceBody.FromCells(HoltburgCells.Fixtures.Values.Select(c => (c.EnvCell, c.CellStruct))));

    internal static PhysicsEngine Engine(string frame = "centred")
    {
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), HoltburgCells.Surfaces());
        engine.AddLandblock(0xA9B3FFFFu, FlatTerrain(GroundZ, 0xA9B3FFFFu), []);
        return engine;
    }

    [Theory]
    [MemberData(nameof(LowDoorways))]
    public void Resolve_DoorwayLowerThanTheBody_StopsItBeforeTheStepAndLetsAShorterOneThrough(string doorway)
    {
        Doorway door = Named(doorway);
        // A ceiling lower than the body's height above the floor it would stand on stops it: the player
        // (1.835 m) stays on its side, never in the door cell; a body 1.2 m tall goes through.
        PhysicsEngine engine = Engine();
        foreach (float degrees in new[] { 0f, 30f, -30f })
        {
            (List<uint> tall, ResolveResult stopped) = BodyDoorways.Walk(engine, Walls.Value, door, degrees, MovementOptions.Player, step: 1.1f)!.Value;
            tall.Should().Equal([tall[0]], $"{door} at {degrees}°: the player stays on its side ({string.Join(" → ", tall.Select(c => $"0x{c:X8}"))}; last {stopped})");
            stopped.Outcome.Should().Be(ResolveOutcome.Wall, $"{door} at {degrees}°: {stopped}");
            BodyDoorways.IsSide(stopped.CellId, door.From).Should().BeTrue($"{door} at {degrees}°: {stopped}");

            var shorter = MovementOptions.Player with { Body = new MoverBody(0.48f, 1.2f) };
            (List<uint> cells, ResolveResult last) = BodyDoorways.Walk(engine, Walls.Value, door, degrees, shorter, step: 1.1f)!.Value;
            BodyDoorways.IsSide(last.CellId, door.To).Should().BeTrue($"{door} at {degrees}°: a 1.2 m body passes ({string.Join(" → ", cells.Select(c => $"0x{c:X8}"))}; last {last})");
        }
    }
}
