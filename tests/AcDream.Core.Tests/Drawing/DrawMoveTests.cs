using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Robustness;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Drawing;

/// <summary>
/// <see cref="PhysicsEngine.DrawMove"/> on the real Holtburg cottage: a walk into a wall draws its sub-steps (chained, the
/// last ending at the answer), a contact along the answer's normal and the floor it stands on; a jump under the main
/// room's ceiling draws the ceiling at 96.8 m; at the small building's plinth, the support under the footprint and the
/// edge held at; the answers are bit for bit those of <c>Resolve</c>, with and without a
/// sink; nothing is allocated per call.
/// </summary>
public class DrawMoveTests(ITestOutputHelper output)
{
    private const uint MainRoom = 0xA9B40143;

    public static TheoryData<string> Frames => new() { "global", "centred" };

    private static MoveRequest Walk(PhysicsEngine engine, Vector3 delta) =>
        new(engine.ToWorld(TestData.Holtburg, new Vector3(138.5f, 6f, 94f)), MainRoom, delta, 0.5f) { Options = MovementOptions.Player, MoverId = 5 };

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_walk_into_a_wall_draws_its_substeps_its_contact_and_its_floor(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        MoveRequest request = Walk(engine, new Vector3(0f, -6f, 0f));
        ResolveResult expected = engine.Resolve(in request).Answer;
        var sink = new RecordingSink();
        ResolveResult answer = engine.DrawMove(in request, sink).Answer;
        Bits(answer).Should().Equal(Bits(expected), "drawing changes nothing of the answer");
        answer.Outcome.Should().BeOneOf([ResolveOutcome.Wall, ResolveOutcome.Slid], $"{frame}: 6 m south from the room's middle meets its wall");
        answer.SurfaceNormal.Should().NotBe(Vector3.Zero);
        output.WriteLine($"[{frame}] {answer.Outcome} at {engine.ToLandblockLocal(TestData.Holtburg, answer.Position)}, normal {answer.SurfaceNormal}");

        Drawn[] steps = sink.Of(DrawKind.SubStep).ToArray();
        steps.Length.Should().BeGreaterThan(1, "a 6 m move sweeps in 0.48 m sub-steps");
        steps[0].Points[0].Should().Be(request.Position);
        steps[^1].Points[1].Should().Be(answer.Position, "the last sub-step ends at the answer");
        for (int i = 1; i < steps.Length; i++)
        {
            steps[i].Points[0].Should().Be(steps[i - 1].Points[1], $"sub-step {i} sets out where sub-step {i - 1} ended");
        }

        sink.All.Should().OnlyContain(d => d.Id == 5u || d.Kind == DrawKind.Floor || d.Kind == DrawKind.Support || d.Kind == DrawKind.Edge);
        Drawn[] contacts = sink.Of(DrawKind.Contact).ToArray();
        contacts.Should().Contain(c => Vector3.Distance(Direction(c), answer.SurfaceNormal) <= 1e-4f + (4f * Distances.Rounding(c.Points[0]) / PhysicsEngine.DrawNormalLength),
            $"{frame}: a contact along the answer's normal {answer.SurfaceNormal}");

        Drawn floor = sink.Of(DrawKind.Floor).Should().ContainSingle().Subject;
        floor.Id.Should().Be(MainRoom);
        Vector3 local = engine.ToLandblockLocal(TestData.Holtburg, answer.Position);
        float tolerance = 1e-4f + Distances.Rounding(answer.Position) + Distances.Rounding(floor.Points[0]);
        Distances.ToTriangle(answer.Position, floor.Points[0], floor.Points[1], floor.Points[2]).Should().BeLessThanOrEqualTo(tolerance, $"{frame}: the floor under {local}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_jump_under_the_main_rooms_ceiling_draws_the_ceiling(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        MoveRequest request = Walk(engine, new Vector3(0f, 0f, 3f));
        ResolveResult expected = engine.Resolve(in request).Answer;
        var sink = new RecordingSink();
        ResolveResult answer = engine.DrawMove(in request, sink).Answer;
        Bits(answer).Should().Equal(Bits(expected));
        answer.Outcome.Should().Be(ResolveOutcome.Ceiling, $"{frame}: a 3 m rise from the floor at 94 m meets the ceiling at 96.8 m");
        Drawn ceiling = sink.Of(DrawKind.Ceiling).Should().ContainSingle().Subject;
        Vector3 at = engine.ToLandblockLocal(TestData.Holtburg, ceiling.Points[0]);
        at.Z.Should().BeApproximately(96.8f, 1e-3f, $"{frame}: the ceiling over the room");
        new Vector2(at.X, at.Y).Should().Be(new Vector2(138.5f, 6f), "over the body's centre");
        Vector3.Distance(Direction(ceiling), answer.SurfaceNormal).Should().BeLessThanOrEqualTo(1e-4f + (4f * Distances.Rounding(ceiling.Points[0]) / PhysicsEngine.DrawNormalLength));
        sink.Of(DrawKind.SubStep).Should().NotBeEmpty();
        sink.Of(DrawKind.SubStep).Last().Points[1].Should().Be(answer.Position);
        output.WriteLine($"[{frame}] ceiling at {at}, normal {answer.SurfaceNormal}, answer {engine.ToLandblockLocal(TestData.Holtburg, answer.Position)}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void Answers_are_bit_for_bit_with_and_without_a_sink(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        engine.Movers.Add(9, MoverShape.Cylinder(0.48f, 1.835f), engine.ToWorld(TestData.Holtburg, new Vector3(141f, 8f, 94f)), MainRoom, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        var random = new Random(3200);
        var sink = new CountingSink();
        int differentOutcomes = 0;
        var outcomes = new HashSet<ResolveOutcome>();
        for (int i = 0; i < 400; i++)
        {
            Vector3 start = engine.ToWorld(TestData.Holtburg, new Vector3(132f + (random.NextSingle() * 14f), 1f + (random.NextSingle() * 12f), 94f + (random.NextSingle() * 2f)));
            uint cell = engine.FindCell(start, MainRoom);
            var delta = new Vector3((random.NextSingle() - 0.5f) * 8f, (random.NextSingle() - 0.5f) * 8f, (random.NextSingle() - 0.3f) * 3f);
            MovementOptions options = (i % 3) switch { 0 => MovementOptions.Player, 1 => new MovementOptions { Body = MoverBody.Player, SweepStepLength = 0.48f }, _ => default };
            var request = new MoveRequest(start, cell, delta, 0.5f) { Options = options, MoverId = (uint)(i % 2) * 9, WithReport = i % 4 == 0 };
            MoveResult plain = engine.Resolve(in request);
            MoveResult drawn = engine.DrawMove(in request, sink);
            MoveResult again = engine.Resolve(in request);
            Bits(drawn.Answer).Should().Equal(Bits(plain.Answer), $"{frame}: request {i} {request}");
            Bits(again.Answer).Should().Equal(Bits(plain.Answer), $"{frame}: request {i} after drawing");
            drawn.Report.Should().Be(plain.Report);
            differentOutcomes += plain.Answer.Outcome == ResolveOutcome.Moved ? 0 : 1;
            outcomes.Add(plain.Answer.Outcome);
        }

        differentOutcomes.Should().BeGreaterThan(50, "the walks meet walls, the ceiling and floors");
        sink.Counts[(int)DrawKind.SubStep].Should().BePositive();
        sink.Counts[(int)DrawKind.Contact].Should().BePositive();
        output.WriteLine($"[{frame}] outcomes {string.Join(", ", outcomes)}; drawn " + string.Join(", ", Enum.GetValues<DrawKind>().Select(k => $"{k} {sink.Counts[(int)k]}")));
    }

    [Fact]
    public void DrawMove_with_a_sink_that_allocates_nothing_allocates_nothing()
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs("centred");
        MoveRequest wall = Walk(engine, new Vector3(0f, -6f, 0f)), jump = Walk(engine, new Vector3(0f, 0f, 3f));
        var sink = new CountingSink();
        for (int i = 0; i < 300; i++)
        {
            _ = engine.DrawMove(in wall, sink); // (warmed up: the JIT's tiers compiled)
            _ = engine.DrawMove(in jump, sink);
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 200; i++)
        {
            _ = engine.DrawMove(in wall, sink);
            _ = engine.DrawMove(in jump, sink);
        }

        (GC.GetAllocatedBytesForCurrentThread() - before).Should().Be(0);
        sink.Counts[(int)DrawKind.Ceiling].Should().Be(500);
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void At_the_plinths_edge_it_draws_the_support_and_the_edge_held_at(string frame)
    {
        PhysicsEngine engine = RealObjects.HoltburgWithCellarStairs(frame);
        Frame plinth = ObjectPlacements.SmallBuildingShell().Frame;
        Vector3 Building(float x, float y, float z)
        {
            (double px, double py, double pz) = ObjectKit.Place(plinth, new Vector3(x, y, z));
            return engine.ToWorld(TestData.Holtburg, new Vector3((float)px, (float)py, (float)pz));
        }

        Vector2 Local(Vector3 world)
        {
            Vector3 v = Vector3.Transform(engine.ToLandblockLocal(TestData.Holtburg, world) - plinth.Origin, Quaternion.Conjugate(Quaternion.Normalize(plinth.Orientation)));
            return new Vector2(v.X, v.Y);
        }

        // 0.076 m past the plinth's east edge (object-local x 4, its top at 96 m): held by the plinth's floor under its footprint.
        var still = new MoveRequest(Building(4.076f, 1f, 2f), 0xA9B40000u, Vector3.Zero, 0.6f) { Options = MovementOptions.Player };
        var sink = new RecordingSink();
        ResolveResult held = engine.DrawMove(in still, sink).Answer;
        Bits(held).Should().Equal(Bits(engine.Resolve(in still).Answer));
        (held.IsOnGround, engine.ToLandblockLocal(TestData.Holtburg, held.Position).Z).Should().Be((true, 96f), $"{frame}: on the plinth");
        sink.Of(DrawKind.Floor).Should().BeEmpty("the ground under its centre (the terrain, 2 m down) does not hold it");
        Drawn support = sink.Of(DrawKind.Support).Should().ContainSingle().Subject;
        float tolerance = 1e-4f + support.Points.Max(Distances.Rounding) + Distances.Rounding(held.Position);
        support.Points.Should().OnlyContain(p => MathF.Abs(p.Z - held.Position.Z) <= tolerance, "the plinth's top is level with the feet");
        Vector3 under = held.Position with { Z = support.Points[0].Z };
        Distances.ToTriangle(under, support.Points[0], support.Points[1], support.Points[2])
            .Should().BeInRange(0.076f - 1e-3f - tolerance, (0.48f * PhysicsConstants.SupportReach) + tolerance, $"{frame}: the support is the plinth's top, its edge 0.076 m from the centre");

        // Head on at the edge, from 0.1 m inside it: edge slide holds it there, at the edge.
        var headOn = new MoveRequest(Building(3.9f, 1f, 2f), 0xA9B40000u, (Building(1f, 0f, 2f) - Building(0f, 0f, 2f)) * 0.5f, 0.6f) { Options = MovementOptions.Player };
        sink = new RecordingSink();
        ResolveResult stopped = engine.DrawMove(in headOn, sink).Answer;
        Bits(stopped).Should().Equal(Bits(engine.Resolve(in headOn).Answer));
        stopped.Outcome.Should().BeOneOf([ResolveOutcome.Edge, ResolveOutcome.Slid], $"{frame}: held at the edge");
        Drawn edge = sink.Of(DrawKind.Edge).Should().ContainSingle().Subject;
        foreach (Vector3 end in edge.Points)
        {
            Local(end).X.Should().BeApproximately(4f, 1e-3f + (2f * Distances.Rounding(end)), $"{frame}: on the plinth's east edge");
            end.Z.Should().Be(headOn.Position.Z, "at the feet's height");
        }

        Vector3.Distance(edge.Points[0], edge.Points[1]).Should().BeApproximately(PhysicsEngine.DrawNormalLength, 1e-4f + (2f * Distances.Rounding(edge.Points[0])));
        output.WriteLine($"[{frame}] held at {engine.ToLandblockLocal(TestData.Holtburg, held.Position)}; head on: {stopped.Outcome}, edge x {Local(edge.Points[0]).X:F5}");
    }

    private static Vector3 Direction(Drawn line) => Vector3.Normalize(line.Points[1] - line.Points[0]);

    /// <summary>An answer's bits: its position's and normal's floats, its cell, ground and outcome.</summary>
    private static long[] Bits(ResolveResult r) =>
    [
        BitConverter.SingleToInt32Bits(r.Position.X), BitConverter.SingleToInt32Bits(r.Position.Y), BitConverter.SingleToInt32Bits(r.Position.Z),
        BitConverter.SingleToInt32Bits(r.SurfaceNormal.X), BitConverter.SingleToInt32Bits(r.SurfaceNormal.Y), BitConverter.SingleToInt32Bits(r.SurfaceNormal.Z),
        r.CellId, r.IsOnGround ? 1 : 0, (long)r.Outcome,
    ];
}
