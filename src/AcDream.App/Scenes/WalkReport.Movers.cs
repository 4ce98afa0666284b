using System.Globalization;
using System.Numerics;
using System.Text;
using AcDream.Core.Physics;
using AcDream.App.World;

namespace AcDream.App.Scenes;

// WalkReport on the movers: what the player's moves touched, the doors, the creatures, and the objects met.
internal static partial class WalkReport
{
    /// <summary>
    /// The movers: the movers the player's moves touched, by id; the doors' states as committed, frame by frame; the
    /// creatures, how far they walked, how often one was held back, and the closest any two movers' centres came.
    /// </summary>
    private static void AddMovers(StringBuilder text, WalkRecord record)
    {
        void Line(FormattableString line) => text.AppendLine(line.ToString(CultureInfo.InvariantCulture));
        var parts = new List<string>();
        foreach (IGrouping<uint, MoverTouch> group in record.Touches.GroupBy(t => t.MoverId))
        {
            int stopped = group.Count(t => t.Stopped);
            parts.Add(string.Create(CultureInfo.InvariantCulture,
                $"0x{group.Key:X8} {MoverName(record, group.Key)}: {FrameCount(group.Count())}{(stopped > 0 ? $" ({stopped} × stopped or slid the player)" : "")}, frames {group.First().Frame}-{group.Last().Frame}, {Legs(record, group.Select(t => t.Frame))}"));
        }

        Line($"Movers met: {(parts.Count == 0 ? "none" : string.Join("; ", parts))}.");
        foreach (IGrouping<uint, DoorChange> door in record.DoorChanges.GroupBy(d => d.DoorId))
        {
            var states = door.ToList();
            var changes = new List<string>();
            for (int i = 0; i < states.Count; i++)
            {
                int leg = LegOf(record, states[i].Frame);
                string held = states[i].State == DoorState.Closing && i + 1 < states.Count
                    ? string.Create(CultureInfo.InvariantCulture, $", held {states[i + 1].Frame - states[i].Frame} frames")
                    : "";
                changes.Add(string.Create(CultureInfo.InvariantCulture, $"{states[i].State.ToString().ToLowerInvariant()} at frame {states[i].Frame}{(leg > 0 ? $" (leg {leg})" : "")}{held}"));
            }

            Line($"Door 0x{door.Key:X8} {MoverName(record, door.Key)}: {string.Join("; ", changes)}.");
        }

        IReadOnlyList<CreaturePath> creatures = record.Creatures;
        if (creatures.Count == 0)
        {
            return;
        }

        int standing = creatures.Count(c => c.Creature.Wander <= 0f);
        float walked = 0f;
        foreach (CreaturePath creature in creatures)
        {
            for (int i = 1; i < creature.Samples.Count; i++)
            {
                walked += creature.Samples[i].Frame == creature.Samples[i - 1].Frame + 1 ? Vector3.Distance(creature.Samples[i].Position, creature.Samples[i - 1].Position) : 0f;
            }
        }

        Line($"Creatures: {creatures.Count} ({creatures.Count - standing} wandering, {standing} standing), ids 0x{creatures[0].Id:X8}..0x{creatures[^1].Id:X8}, each an upright cylinder of radius {MoverBody.Player.Radius} m, {MoverBody.Player.Height} m tall; walked {walked:F1} m in all; held back {creatures.Sum(c => c.HeldBack)} frames (a creature's answer ended inside a mover that had moved first that frame).");
        (float between, uint a, uint b, int atFrame) = record.ClosestCreatures();
        (float toPlayer, uint c, int playerFrame) = record.ClosestToPlayer();
        Line($"Closest centres: two creatures {between:F3} m apart (0x{a:X8} and 0x{b:X8} at frame {atFrame}); a creature and the player {toPlayer:F3} m (0x{c:X8} at frame {playerFrame}).");
        foreach (CreaturePath creature in creatures)
        {
            foreach ((int frame, uint landblock) in creature.Removed)
            {
                Line($"Creature 0x{creature.Id:X8} left with its landblock 0x{Landblock(landblock)} at frame {frame}.");
            }
        }
    }

    /// <summary>A leg's movers touched, when it touched any: each id with its name and frames.</summary>
    private static string DescribeLegMovers(WalkRecord record, LegResult leg)
    {
        var parts = record.Touches.Where(t => t.Frame >= leg.FirstFrame && t.Frame <= leg.LastFrame).GroupBy(t => t.MoverId)
            .Select(g => string.Create(CultureInfo.InvariantCulture, $"0x{g.Key:X8} {MoverName(record, g.Key)} ({FrameCount(g.Count())})")).ToList();
        return parts.Count == 0 ? "" : "; movers met: " + string.Join(", ", parts);
    }

    /// <summary>"1 frame", "n frames".</summary>
    private static string FrameCount(int frames) => string.Create(CultureInfo.InvariantCulture, $"{frames} frame{(frames == 1 ? "" : "s")}");

    /// <summary>A mover's short name: the door's, "creature", "player", or "mover".</summary>
    private static string MoverName(WalkRecord record, uint id) =>
        HoltburgWorld.ObjectName(id) ?? (id == SceneRunner.PlayerId ? "player" : record.Creatures.Any(c => c.Id == id) ? "creature" : "mover");

    /// <summary>The number (1-based) of the leg frame <paramref name="frame"/> belongs to; 0 before the first.</summary>
    private static int LegOf(WalkRecord record, int frame) =>
        1 + record.Legs.ToList().FindIndex(l => frame >= l.FirstFrame && frame <= l.LastFrame);

    /// <summary>"leg n" or "legs n, m" for the legs of <paramref name="frames"/>.</summary>
    private static string Legs(WalkRecord record, IEnumerable<int> frames)
    {
        var legs = frames.Select(f => LegOf(record, f)).Where(l => l > 0).Distinct().ToList();
        return $"leg{(legs.Count == 1 ? "" : "s")} {string.Join(", ", legs)}";
    }

    /// <summary>Per object id (nonzero <paramref name="idOf"/>): its frames, first and last, the outcomes (<paramref name="kindOf"/>) and the legs.</summary>
    private static string DescribeObjects(WalkRecord record, Func<FrameSample, uint> idOf, Func<FrameSample, string?> kindOf)
    {
        var parts = new List<string>();
        foreach (IGrouping<uint, FrameSample> group in record.Samples.Where(s => idOf(s) != 0).GroupBy(idOf))
        {
            string name = World.HoltburgWorld.ObjectName(group.Key) is string n ? $" {n}" : "";
            string kinds = string.Join(", ", group.Select(kindOf).Where(k => k is not null).GroupBy(k => k).Select(k => $"{k.Count()} × {k.Key}"));
            var legs = new List<int>();
            foreach (FrameSample sample in group)
            {
                int leg = 1 + record.Legs.ToList().FindIndex(l => sample.Frame >= l.FirstFrame && sample.Frame <= l.LastFrame);
                if (leg > 0 && !legs.Contains(leg))
                {
                    legs.Add(leg);
                }
            }

            parts.Add(string.Create(CultureInfo.InvariantCulture,
                $"0x{group.Key:X8}{name}: {group.Count()} frames{(kinds.Length > 0 ? $" ({kinds})" : "")}, frames {group.First().Frame}-{group.Last().Frame}, leg{(legs.Count == 1 ? "" : "s")} {string.Join(", ", legs)}"));
        }

        return parts.Count == 0 ? "none" : string.Join("; ", parts);
    }
}
