using System.Numerics;
using AcDream.Core.Physics;

namespace AcDream.Core.Tests.Api;

/// <summary>
/// The general calls (<see cref="PhysicsEngine.Resolve(in MoveRequest, Span{uint})"/>, <see cref="PhysicsEngine.Cast(in CastRequest)"/>)
/// and the questions a client asks: which cell holds a point (<see cref="PhysicsEngine.FindCell"/>) and which commit a move read.
/// </summary>
public class RequestTests
{
    private const uint MainRoom = 0xA9B40143, Cellar = 0xA9B40147, DoorCell = 0xA9B40145;

    public static TheoryData<string> Frames => new() { "global", "centred" };

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_request_answers_as_the_calls_it_replaces_bit_for_bit(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        var random = new Random(31);
        uint[] cells = [0, MainRoom, Cellar, DoorCell];
        for (int n = 0; n < 400; n++)
        {
            uint cell = cells[n % cells.Length];
            Vector3 local = cell == 0 ? new Vector3(100 + (random.NextSingle() * 60), random.NextSingle() * 40, 94f)
                : cell == Cellar ? new Vector3(137.6f + (random.NextSingle() * 2.4f), 1f + (random.NextSingle() * 9f), 91.6f)
                : new Vector3(137.6f + (random.NextSingle() * 3.4f), 5f + (random.NextSingle() * 7f), 94f);
            Vector3 at = engine.ToWorld(TestData.Holtburg, local), delta = new((random.NextSingle() - 0.5f) * 3f, (random.NextSingle() - 0.5f) * 3f, 0f);
            ResolveResult start = engine.Resolve(at, cell, Vector3.Zero, 0.6f);
            string what = $"{frame}, case {n}: from {start.Position} in 0x{start.CellId:X8} by {delta}";
            engine.Resolve(new MoveRequest(start.Position, start.CellId, delta, 0.6f)).Answer.Should().Be(engine.Resolve(start.Position, start.CellId, delta, 0.6f), what);
            MoveResult player = engine.Resolve(new MoveRequest(start.Position, start.CellId, delta, 0.6f) { Options = MovementOptions.Player, WithReport = true });
            player.Answer.Should().Be(engine.Resolve(start.Position, start.CellId, delta, 0.6f, MovementOptions.Player), what);
            (player.Report.Floor.Kind != SurfaceKind.None).Should().Be(player.Answer.IsOnGround, $"{what}: the floor is named exactly when on the ground");
            (player.TouchedCount, player.Commit).Should().Be((0, 0L), $"{what}: no movers, no commit");
        }
    }

    [Fact]
    [Trait("Mutation", "MoverRegistry")]
    public void The_touched_movers_fill_the_span_in_the_order_met_and_are_counted_beyond_it_and_the_commit_is_named()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        Vector3 Local(float x, float y) => engine.ToWorld(TestData.Holtburg, new Vector3(x, y, 94f));
        MoverState ghost = MoverState.Creature with { Physics = PhysicsStateFlags.Ethereal };
        engine.Movers.CommitNumber.Should().Be(0);
        engine.Movers.Add(7, MoverShape.Cylinder(0.2f, 1f), Local(40f, 42f), 0, Quaternion.Identity, ghost);
        engine.Movers.Add(5, MoverShape.Cylinder(0.2f, 1f), Local(40f, 41f), 0, Quaternion.Identity, ghost);
        engine.Movers.Add(6, MoverShape.Cylinder(0.2f, 1f), Local(40f, 43f), 0, Quaternion.Identity, ghost);
        engine.Movers.Commit();
        engine.Movers.Commit();
        engine.Movers.CommitNumber.Should().Be(2);

        var request = new MoveRequest(Local(40f, 40f), 0, new Vector3(0f, 4f, 0f), 0.6f) { Options = MovementOptions.Player };
        Span<uint> two = stackalloc uint[2];
        MoveResult result = engine.Resolve(in request, two);
        (result.TouchedCount, result.Commit).Should().Be((3, 2L), "three touched along the path, read at the second commit");
        two.ToArray().Should().Equal([5u, 7u], "the first two met along the path");
        engine.Resolve(in request).Should().Be(result with { TouchedCount = 0 }, "an empty span looks for no touches; the answer is the same");

        engine.Movers.Move(5, Local(80f, 80f), 0, Quaternion.Identity);
        engine.Resolve(in request, two).Commit.Should().Be(2L, "the move is not committed yet");
        engine.Movers.Commit();
        MoveResult after = engine.Resolve(in request, two);
        (after.TouchedCount, after.Commit).Should().Be((2, 3L), "the third commit moved mover 5 away");
        engine.Resolve(request with { Position = Local(10f, 10f) }).Commit.Should().Be(3L, "a move with no mover near names the commit in effect");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void FindCell_follows_portals_from_the_hint_and_else_names_the_outdoor_cell(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        Vector3 Local(float x, float y, float z) => engine.ToWorld(TestData.Holtburg, new Vector3(x, y, z));
        float cellarFloor = HoltburgCells.Surface(Cellar).SampleFloorZ(139f, 5f)!.Value;

        engine.FindCell(Local(139.2f, 10.5f, 94.5f), MainRoom).Should().Be(MainRoom, "in the room, the room");
        engine.FindCell(Local(139.2f, 10.5f, 94.5f), 0).Should().Be(MainRoom, "from outdoors, in through the door");
        engine.FindCell(Local(139f, 5f, cellarFloor + 0.5f), MainRoom).Should().Be(Cellar, "down through the stairwell's portals");
        engine.FindCell(Local(139.2f, 10.5f, 110f), MainRoom).Should().Be(0xA9B40029u, "above the roof: the outdoor cell");
        engine.FindCell(Local(100f, 100f, 95f), MainRoom).Should().Be(0xA9B40025u, "far outdoors: the outdoor cell (x 100 → 4, y 100 → 4)");

        // Every answer of a walk in through the cottage's west door is held by the cell FindCell names, from the one before.
        var character = new Character(engine, new CharacterSettings(), Local(128f, 5.6f, 94f), 0);
        Vector3[] route = [Local(134f, 5.6f, 94f), Local(139f, 6f, 94f), Local(139.2f, 10.5f, 94f)];
        uint hint = character.CellId;
        var visited = new HashSet<uint>();
        for (int i = 0; i < 200; i++)
        {
            Vector3 towards = route[Math.Min(i / 70, route.Length - 1)] - character.Position;
            CharacterStep step = character.Update(1f / 30f, Vector2.Normalize(new Vector2(towards.X, towards.Y)) * 2f, jump: false);
            if (step.IsOnGround)
            {
                engine.FindCell(step.Position + new Vector3(0f, 0f, 0.01f), hint).Should().Be(step.CellId, $"{frame}, frame {i}: at {step.Position}");
            }

            hint = step.CellId;
            visited.Add(hint);
        }

        visited.Should().Contain([DoorCell, MainRoom], $"{frame}: the walk went in by the door");

        Action nan = () => engine.FindCell(new Vector3(float.NaN, 0f, 0f), 0);
        nan.Should().Throw<ArgumentException>().WithParameterName("position");
        Action bad = () => engine.FindCell(Local(1f, 1f, 94f), 0xA9B40041);
        bad.Should().Throw<ArgumentException>().WithParameterName("hintCellId").WithMessage("*0xA9B40041*");
    }

    [Fact]
    public void A_cast_request_goes_along_its_delta_and_passes_its_mover()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        Vector3 from = engine.ToWorld(TestData.Holtburg, new Vector3(40f, 40f, 95f));
        engine.Movers.Add(3, MoverShape.Cylinder(0.5f, 2f), from + new Vector3(3f, 0f, -1f), 0, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        var request = new CastRequest(from, 0, new Vector3(6f, 0f, 0f)) { Options = new CastOptions(0.2f) };
        CastHit hit = engine.Cast(in request);
        (hit.Hit, hit.Kind, hit.Id).Should().Be((true, SurfaceKind.Mover, 3u));
        hit.Position.X.Should().BeApproximately(from.X + 3f - 0.5f - 0.2f, 1e-4f, "stopped its radius short of the cylinder");
        CastHit passed = engine.Cast(request with { MoverId = 3 });
        (passed.Hit, passed.Position).Should().Be((false, from + request.Delta), "its own mover passed: it ends at From + Delta");
    }
}
