using System.Numerics;
using AcDream.Core.Physics;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Moving;

/// <summary>
/// The game's rules of who collides with whom, end to end: a body walks at a registered target in every combination of
/// the mover's and the target's kind and bits; the answer is stopped exactly when the rules say the target blocks, and
/// the target is named as touched exactly when it is met.
/// </summary>
[Trait("Mutation", "MoverRegistry")]
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
public class MoverRuleTests(ITestOutputHelper output)
{
    private static readonly ObjectDescriptionFlags[] PlayerBits =
    [
        ObjectDescriptionFlags.None, ObjectDescriptionFlags.PlayerKiller, ObjectDescriptionFlags.PkLite, ObjectDescriptionFlags.Impenetrable,
        ObjectDescriptionFlags.PlayerKiller | ObjectDescriptionFlags.Impenetrable, ObjectDescriptionFlags.PkLite | ObjectDescriptionFlags.Impenetrable,
        ObjectDescriptionFlags.PlayerKiller | ObjectDescriptionFlags.PkLite,
    ];

    private static IEnumerable<(string Name, MoverState State)> Targets()
    {
        foreach (PhysicsStateFlags physics in new[] { PhysicsStateFlags.None, PhysicsStateFlags.Ethereal, PhysicsStateFlags.IgnoreCollisions, PhysicsStateFlags.Ethereal | PhysicsStateFlags.IgnoreCollisions })
        {
            yield return ($"object {physics}", new MoverState(MoverKind.Object, physics));
            yield return ($"creature {physics}", new MoverState(MoverKind.Creature, physics));
            foreach (ObjectDescriptionFlags bits in PlayerBits)
            {
                yield return ($"player {bits} {physics}", new MoverState(MoverKind.Creature, physics, ObjectDescriptionFlags.Player | bits));
            }
        }
    }

    private static IEnumerable<(string Name, MoverState State)> Walkers()
    {
        foreach (bool ignores in new[] { false, true })
        {
            yield return ($"object ignores={ignores}", new MoverState(MoverKind.Object, IgnoresCreatures: ignores));
            yield return ($"creature ignores={ignores}", new MoverState(MoverKind.Creature, IgnoresCreatures: ignores));
            foreach (ObjectDescriptionFlags bits in PlayerBits)
            {
                yield return ($"player {bits} ignores={ignores}", new MoverState(MoverKind.Creature, Description: ObjectDescriptionFlags.Player | bits, IgnoresCreatures: ignores));
            }
        }
    }

    /// <summary>The rules as the game states them, one by one.</summary>
    private static (bool Met, bool Blocks) Rule(MoverState walker, MoverState target)
    {
        bool ethereal = target.Physics.HasFlag(PhysicsStateFlags.Ethereal);
        if (ethereal && target.Physics.HasFlag(PhysicsStateFlags.IgnoreCollisions))
        {
            return (false, false); // skipped
        }

        if (ethereal)
        {
            return (true, false); // touched, not blocking
        }

        bool targetPlayer = target.Description.HasFlag(ObjectDescriptionFlags.Player);
        bool walkerPlayer = walker.Description.HasFlag(ObjectDescriptionFlags.Player);
        if (walker.IgnoresCreatures && (target.Kind == MoverKind.Creature || targetPlayer))
        {
            return (true, false);
        }

        if (walkerPlayer && targetPlayer)
        {
            bool impenetrable = walker.Description.HasFlag(ObjectDescriptionFlags.Impenetrable) || target.Description.HasFlag(ObjectDescriptionFlags.Impenetrable);
            bool bothPk = walker.Description.HasFlag(ObjectDescriptionFlags.PlayerKiller) && target.Description.HasFlag(ObjectDescriptionFlags.PlayerKiller);
            bool bothLite = walker.Description.HasFlag(ObjectDescriptionFlags.PkLite) && target.Description.HasFlag(ObjectDescriptionFlags.PkLite);
            return (true, impenetrable || bothPk || bothLite);
        }

        return (true, true);
    }

    [Theory]
    [InlineData("body")]
    [InlineData("point")]
    public void Every_combination_blocks_and_is_touched_as_the_rules_say(string mover)
    {
        PhysicsEngine engine = MoverSmokeTests.Field();
        Vector3 target = MoverSmokeTests.World(engine, MoverSmokeTests.Axis);
        Vector3 start = target - new Vector3(2f, 0f, 0f);
        MovementOptions options = mover == "body" ? MovementOptions.Player : new MovementOptions { SweepStepLength = 0.48f };
        engine.Movers.Add(1, MoverKit.Human, start, MoverSmokeTests.Outdoor, Quaternion.Identity, MoverState.Player);
        engine.Movers.Add(2, MoverKit.Human, target, MoverSmokeTests.Outdoor, Quaternion.Identity, MoverState.Creature);
        Span<uint> touched = stackalloc uint[4];
        int cases = 0, blocked = 0, met = 0;
        foreach ((string walkerName, MoverState walker) in Walkers())
        {
            foreach ((string targetName, MoverState state) in Targets())
            {
                engine.Movers.SetState(1, walker);
                engine.Movers.SetState(2, state);
                engine.Movers.Commit();
                ResolveResult r = engine.Resolve(start, MoverSmokeTests.Outdoor, new Vector3(4f, 0f, 0f), 0.6f, options, 1u, touched, out int count, out _);
                (bool expectMet, bool expectBlocks) = Rule(walker, state);
                string what = $"{walkerName} at {targetName}: {r}, touched {count}";
                (r.Position.X < target.X - (mover == "body" ? 0.9f : 0.45f)).Should().Be(expectBlocks, what);
                count.Should().Be(expectMet ? 1 : 0, what);
                if (expectMet)
                {
                    touched[0].Should().Be(2u, what);
                }

                (cases, blocked, met) = (cases + 1, blocked + (expectBlocks ? 1 : 0), met + (expectMet ? 1 : 0));
            }
        }

        output.WriteLine($"{cases} combinations: {blocked} block, {met} met");
        cases.Should().Be(18 * 36);
    }
}
