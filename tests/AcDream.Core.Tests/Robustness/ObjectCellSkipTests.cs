using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// A move far from every object skips the objects by one bit of its outdoor cell (objects on the cell
/// or within one 4 m square of it); the skip must never miss one. Trees stand just inside and just
/// beyond that square around cell edges and corners, and seeded moves of 0.05–10 m (short ones the
/// bit answers for, long ones it does not) start around them. A move whose path clearly meets a trunk
/// is stopped by it; one that clearly misses every trunk answers bit for bit as in a landblock without
/// the trees. In both world frames; the literal call and the player (whose body keeps its radius from
/// every trunk).
/// </summary>
[Trait("Mutation", "ObjectQueries")]
public class ObjectCellSkipTests(ITestOutputHelper output)
{
    private const uint Landblock = 0x4C5DFFFF;
    private const uint Outdoor = 0x4C5D0000;
    private const float TerrainZ = 50f;
    private const float TreeRadius = 0.4f;

    /// <summary>Trees near cell edges (24 m) and corners: inside a cell, 0.3–0.6 m past an edge, and 3.7–4.6 m past one (about one square).</summary>
    private static readonly Vector2[] Trees =
    [
        new(24.5f, 40f), new(47.5f, 70f), new(75.9f, 100f), new(124.6f, 130f), new(150f, 95.7f),
        new(144.2f, 167.8f), new(10f, 172.4f), new(100f, 52.1f), new(168.3f, 20f), new(187.9f, 187.9f),
    ];

    public static TheoryData<string, string> Cases() => new()
    {
        { "global", "literal" }, { "global", "Player" }, { "centred", "literal" }, { "centred", "Player" },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void The_skip_never_misses_a_trunk_and_a_clear_move_answers_as_without_trees(string frame, string effects)
    {
        MovementOptions options = effects == "Player" ? MovementOptions.Player : MovementOptions.Literal;
        float body = effects == "Player" ? MoverBody.Player.Radius : 0f;
        (Setup tree, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree(TreeRadius, 5f);
        var objects = Trees.Select(t => new ObjectSurface(tree, parts, ObjectKit.At(new Vector3(t, TerrainZ), 0f), 0)).ToList();
        PhysicsEngine withTrees = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Landblock);
        PhysicsEngine without = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Landblock);
        withTrees.AddLandblock(Landblock, TestData.FlatTerrain(TerrainZ, Landblock), [], objects);
        without.AddLandblock(Landblock, TestData.FlatTerrain(TerrainZ, Landblock), []);
        Vector3 origin = withTrees.GetLandblockOrigin(Landblock);
        var random = new Random(frame.Length + (3 * effects.Length));
        float[][] lengths = [[0.05f, 1f], [1f, 3.9f], [3.9f, 4.1f], [4.1f, 10f]];
        int stopped = 0, clear = 0, moves = 0;
        while (moves < 4000)
        {
            Vector2 near = Trees[random.Next(Trees.Length)];
            var start = near + new Vector2((float)((random.NextDouble() * 16) - 8), (float)((random.NextDouble() * 16) - 8));
            float[] range = lengths[random.Next(lengths.Length)];
            float length = range[0] + (float)(random.NextDouble() * (range[1] - range[0]));
            Vector2 toward = near - start; // half the moves head for the tree
            float heading = random.Next(2) == 0 ? MathF.Atan2(toward.Y, toward.X) + (float)((random.NextDouble() - 0.5) * 0.2) : (float)(random.NextDouble() * 2 * Math.PI);
            var move = new Vector2(MathF.Cos(heading) * length, MathF.Sin(heading) * length);
            Vector2 end = start + move;
            if (start.X < 1f || start.Y < 1f || start.X > 191f || start.Y > 191f || end.X < 1f || end.Y < 1f || end.X > 191f || end.Y > 191f
                || Trees.Any(t => Vector2.Distance(t, start) < TreeRadius + body + 0.05f))
            {
                continue;
            }

            moves++;
            double nearest = Trees.Min(t => ReferenceBody.Distance(new(t.X, t.Y), new(start.X, start.Y), new(end.X, end.Y)));
            var position = origin + new Vector3(start, TerrainZ);
            var delta = new Vector3(move, 0f);
            string what = $"{frame}, {effects}: from {start:R} by {move:R} (nearest trunk axis {nearest:R} m from the path)";
            ResolveResult r = withTrees.Resolve(position, Outdoor, delta, 0.5f, in options);
            if (nearest < TreeRadius - 1e-3)
            {
                stopped++;
                if (body == 0f)
                {
                    r.Outcome.Should().Be(ResolveOutcome.Wall, what);
                    r.Position.Should().Be(position, what);
                }
            }
            else if (nearest > TreeRadius + body + 0.25f)
            {
                clear++;
                ResolveResult bare = without.Resolve(position, Outdoor, delta, 0.5f, in options);
                if (body == 0f || length <= options.SweepStepLength)
                {
                    r.Should().Be(bare, what);
                }
                else
                {
                    // A body with a trunk in the box of a long move plans its path (no contact) and aims each
                    // sub-step at its point of it; on open ground its sub-steps are the point's own, each
                    // rounded to the world frame from the last: the same move, within half a float step of
                    // the position per sub-step.
                    (r.Outcome, r.CellId, r.IsOnGround).Should().Be((bare.Outcome, bare.CellId, bare.IsOnGround), what);
                    double steps = Math.Ceiling(length / options.SweepStepLength!.Value);
                    ((double)Vector3.Distance(r.Position, bare.Position)).Should().BeLessThanOrEqualTo(steps * BodyCheck.Spacing(position, delta), what);
                }
            }

            var at = new Vector2(r.Position.X - origin.X, r.Position.Y - origin.Y);
            Trees.Min(t => Vector2.Distance(t, at)).Should().BeGreaterThanOrEqualTo(TreeRadius + body - 1e-3f, $"{what} → {r}");
        }

        output.WriteLine($"{frame}, {effects}: {moves} moves, {stopped} through a trunk's circle, {clear} clear of every trunk");
        stopped.Should().BeGreaterThan(100);
        clear.Should().BeGreaterThan(1000);
    }
}
