using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// The body's open-ground shortcut: where no wall lies in the box the body sweeps (its start and end
/// grown by its radius, skin and the contact tolerance), <c>Resolve</c> answers with the point's move and
/// never plans the body's path. Wherever it does, the plan must give the same answer bit for bit. Seeded
/// moves of 0.05–3 m outdoors around the real Holtburg cells' walls, the cottage and small-building
/// shells and a row of trees, in both world frames, with the body alone and the player's effects, each
/// answered by <c>Resolve</c> and by the body's plan called directly. (A swept move, longer than the
/// player's sweep step, is the same move rounded differently: within half a float step per sub-step.)
/// </summary>
public class BodyOpenGroundTests(ITestOutputHelper output)
{
    private const float GroundZ = 94f;

    public static TheoryData<string, string> Cases() => new()
    {
        { "global", "body" }, { "global", "Player" }, { "centred", "body" }, { "centred", "Player" },
    };

    [Theory]
    [MemberData(nameof(Cases))]
    public void Where_the_shortcut_skips_the_plan_the_plan_answers_the_same(string frame, string effects)
    {
        MovementOptions options = effects == "Player" ? MovementOptions.Player : new MovementOptions { Body = MoverBody.Player };
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(Holtburg);
        List<ObjectSurface> objects = RealObjects.HoltburgBuildings();
        (Setup tree, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree(0.5f, 6f);
        for (int k = 0; k < 8; k++)
        {
            objects.Add(new ObjectSurface(tree, parts, ObjectKit.At(new Vector3(100f + (3.1f * k), 20f + (1.3f * k), GroundZ), 0f), 0));
        }

        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ), HoltburgCells.Surfaces(), objects);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        var random = new Random(frame.Length + effects.Length);
        int shortcut = 0, planned = 0, nearWall = 0;
        for (int m = 0; m < 6000; m++)
        {
            var start = new Vector2(95f + (float)(random.NextDouble() * 80), 2f + (float)(random.NextDouble() * 50));
            float length = 0.05f + (float)(random.NextDouble() * (random.Next(3) == 0 ? 3 : 0.5));
            float heading = (float)(random.NextDouble() * 2 * Math.PI);
            var move = new Vector2(MathF.Cos(heading) * length, MathF.Sin(heading) * length);
            ResolveResult at = engine.Resolve(origin + new Vector3(start, GroundZ), 0xA9B40000, Vector3.Zero, 0.6f, in options);
            if (CellIds.IsIndoor(at.CellId) || at.Outcome != ResolveOutcome.Moved || engine.BodyOverlap(at.Position, at.CellId, 0.6f, MoverBody.Player) > 0f)
            {
                continue; // indoors (always planned), or a start the body does not stand clear at
            }

            string what = $"{frame}, {effects}: from {at.Position - origin:R} by {move:R}";
            var delta = new Vector3(move, 0f);
            ResolveResult answer = engine.Resolve(at.Position, at.CellId, delta, 0.6f, in options);
            ResolveResult plan = engine.ResolvePlanned(at.Position, at.CellId, move, 0.6f, in options);
            if (engine.IsOpenGround(at.Position, at.CellId, move, MoverBody.Player))
            {
                shortcut++;
                if (options.SweepStepLength is float sweep && length > sweep)
                {
                    // Swept: the plan aims each sub-step at its point of the path, the point's own sweep steps
                    // on from where the last sub-step was rounded to: the same move, within half a float step
                    // of the position per sub-step.
                    (answer.Outcome, answer.CellId, answer.IsOnGround).Should().Be((plan.Outcome, plan.CellId, plan.IsOnGround), what);
                    ((double)Vector3.Distance(answer.Position, plan.Position)).Should().BeLessThanOrEqualTo(Math.Ceiling(length / sweep) * BodyCheck.Spacing(at.Position, delta), what);
                }
                else
                {
                    answer.Should().Be(plan, what);
                }

                nearWall += engine.BodyOverlap(at.Position, at.CellId, 0.6f, new MoverBody(length + 1.5f, 2f)) > 0f ? 1 : 0;
            }
            else
            {
                planned++;
            }
        }

        output.WriteLine($"{frame}, {effects}: {shortcut} moves took the shortcut ({nearWall} of them within 1.5 m of a wall beyond their length), {planned} were planned");
        shortcut.Should().BeGreaterThan(1000);
        planned.Should().BeGreaterThan(300);
        nearWall.Should().BeGreaterThan(100, "the shortcut is tried beside walls, not only in the open");
    }
}
