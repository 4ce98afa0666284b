using System.Numerics;
using AcDream.Core.Physics;
using Xunit.Abstractions;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Where four landblocks meet: Holtburg and its east, north and north-east neighbours, each with 40 trees (0.4 m
/// trunks) within 8 m of the shared corner, some standing up to 1.5 m past their own landblock's edges. Bodies moving
/// 0.1–3 m from random clear starts in all four landblocks (moves that reach two, three and four of them) never end
/// more than 1 mm inside a trunk, measured in double precision against every tree; and the moves meet trunks of
/// each landblock. Both world frames, the body alone and <see cref="MovementOptions.Player"/>.
/// </summary>
public class CornerTests(ITestOutputHelper output)
{
    private const float GroundZ = 94f, Trunk = 0.4f;
    private static readonly uint[] Landblocks = [Holtburg, 0xAAB4FFFFu, 0xA9B5FFFFu, 0xAAB5FFFFu];

    [Theory]
    [InlineData("global", false)]
    [InlineData("centred", false)]
    [InlineData("global", true)]
    [InlineData("centred", true)]
    public void Bodies_at_a_corner_of_four_landblocks_never_end_inside_a_trunk(string frame, bool player)
    {
        var random = new Random(player ? 43 : 41);
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        var tree = ObjectKit.Tree(Trunk, 5f);
        var trunks = new List<(Vector2 Centre, int Landblock)>(); // Holtburg-local
        for (int lb = 0; lb < Landblocks.Length; lb++)
        {
            var shift = new Vector2((lb & 1) * 192f, (lb >> 1) * 192f); // its frame's offset from Holtburg's
            var objects = new List<ObjectSurface>();
            for (int i = 0; i < 40; i++)
            {
                // Within 8 m of the corner (192, 192) of Holtburg's frame, on this landblock's side of it or up to 1.5 m past.
                Vector2 local = new Vector2(192f, 192f) - shift + new Vector2(Side(random, lb & 1), Side(random, lb >> 1));
                objects.Add(new ObjectSurface(tree.Setup, tree.Parts, ObjectKit.At(new Vector3(local, GroundZ), 0f), 0));
                trunks.Add((local + shift, lb));
            }

            engine.AddLandblock(Landblocks[lb], FlatTerrain(GroundZ, Landblocks[lb]), [], objects);
        }

        MovementOptions options = player ? MovementOptions.Player : new MovementOptions { Body = MoverBody.Player };
        float reach = Trunk + MoverBody.Player.Radius;
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        int moves = 0, met = 0;
        var metIn = new int[Landblocks.Length];
        double worst = double.PositiveInfinity;
        while (moves < 600)
        {
            var start = new Vector2(184f + (16f * random.NextSingle()), 184f + (16f * random.NextSingle()));
            if (trunks.Any(t => Vector2.Distance(t.Centre, start) < reach + 0.01f))
            {
                continue;
            }

            float angle = random.NextSingle() * MathF.Tau, length = 0.1f + (2.9f * random.NextSingle());
            var delta = new Vector3(MathF.Cos(angle) * length, MathF.Sin(angle) * length, 0f);
            ResolveResult r = engine.Resolve(origin + new Vector3(start, GroundZ), 0, delta, 0.6f, in options);
            moves++;
            var end = new Vector2((float)((double)r.Position.X - origin.X), (float)((double)r.Position.Y - origin.Y));
            foreach ((Vector2 centre, int lb) in trunks)
            {
                double gap = Math.Sqrt(Math.Pow((double)r.Position.X - origin.X - centre.X, 2) + Math.Pow((double)r.Position.Y - origin.Y - centre.Y, 2)) - reach;
                worst = Math.Min(worst, gap);
                gap.Should().BeGreaterThan(-1e-3, $"{frame}: from {start} by {delta} → {end} ({r}): inside the trunk at {centre} of landblock {lb}");
                if (gap < 1e-2 && r.Outcome is ResolveOutcome.Slid or ResolveOutcome.Wall)
                {
                    met++;
                    metIn[lb]++;
                }
            }
        }

        output.WriteLine($"{frame}, {(player ? "Player" : "body")}: {moves} moves, {met} ended against a trunk (by landblock {string.Join(", ", metIn)}), nearest {worst * 1000:F3} mm");
        metIn.Should().OnlyContain(n => n > 0, $"moves met trunks of every landblock: {string.Join(", ", metIn)}");
    }

    /// <summary>An offset from the corner along one axis: 0–8 m into this landblock's side, or up to 1.5 m past its edge.</summary>
    private static float Side(Random random, int far) => (far == 0 ? -1f : 1f) * ((9.5f * random.NextSingle()) - 1.5f);
}
