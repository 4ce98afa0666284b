using System.Globalization;
using System.Numerics;
using AcDream.Core.Physics;
using AcDream.App.Movement;

namespace AcDream.App.Scenes;

// WalkReport's descriptions: effects, slides, outcomes, airborne frames, refusals and seams in words.
internal static partial class WalkReport
{
    /// <summary>Short text for the opt-in effects a scene uses.</summary>
    private static string DescribeEffects(MovementOptions effects)
    {
        var on = new List<string>();
        if (effects.StepDownHeight is float down)
        {
            on.Add(FormattableString.Invariant($"step down {down} m (falls under gravity)"));
        }

        if (effects.WalkableSlope)
        {
            on.Add("walkable slope");
        }

        if (effects.SweepStepLength is float sweep)
        {
            on.Add(FormattableString.Invariant($"swept in {sweep} m sub-steps"));
        }

        if (effects.DoorsOnly)
        {
            on.Add("doors only");
        }

        if (effects.Body is MoverBody body)
        {
            on.Add(FormattableString.Invariant($"a body (an upright cylinder of radius {body.Radius} m, {body.Height} m tall) that slides along walls"));
            if (effects.Vertical)
            {
                on.Add("vertical motion (jumps and falls swept: ceilings stop them, the first floor lands them)");
            }

            if (effects.Footing)
            {
                on.Add("footing under the body (half its radius past an edge)");
            }

            if (effects.EdgeSlide)
            {
                on.Add("edge slide");
            }
        }

        return on.Count == 0 ? "none (the spec's literal engine)" : string.Join(", ", on);
    }

    /// <summary>
    /// A leg's slides, from the engine's normals (<see cref="ResolveResult.SurfaceNormal"/>, one per
    /// slid frame, in frame order): along walls (a horizontal normal, pointing at the mover) and, with
    /// walkable slope, along the contour of a slope too steep to climb (the slope's normal, with a Z).
    /// Each kind gives its frames and its normal, or, when its normals differ (a rounded corner), how
    /// many differ and the first and last, each rounded to 0.01.
    /// </summary>
    public static string DescribeSlides(IReadOnlyList<Vector3> normals)
    {
        var parts = new List<string>();
        foreach (bool walls in (ReadOnlySpan<bool>)[true, false])
        {
            var distinct = new List<string>();
            int frames = 0;
            foreach (Vector3 n in normals)
            {
                if (IsWall(n) != walls)
                {
                    continue;
                }

                frames++;
                string text = walls
                    ? FormattableString.Invariant($"({Round(n.X):F2}, {Round(n.Y):F2})")
                    : FormattableString.Invariant($"({Round(n.X):F2}, {Round(n.Y):F2}, {Round(n.Z):F2})");
                if (!distinct.Contains(text))
                {
                    distinct.Add(text);
                }
            }

            if (frames > 0)
            {
                string along = walls ? (distinct.Count == 1 ? "a wall" : "walls") : (distinct.Count == 1 ? "a slope's contour" : "slopes' contours");
                parts.Add(distinct.Count == 1
                    ? $"{frames} × along {along}, normal {distinct[0]}"
                    : $"{frames} × along {along}, {distinct.Count} normals from {distinct[0]} to {distinct[^1]}");
            }
        }

        return string.Join(", ", parts);
    }

    /// <summary>A slide's normal is a wall's when it is horizontal (the engine's walls are); a slope's has a Z.</summary>
    private static bool IsWall(Vector3 normal) => normal.Z == 0f;

    /// <summary>Rounded to 0.01, without a negative zero.</summary>
    private static float Round(float value) => MathF.Round(value, 2) + 0f;

    /// <summary>Short text for one of the engine's outcomes, 1:1 (the engine's reason, not a guess).</summary>
    public static string Describe(ResolveOutcome outcome) => outcome switch
    {
        ResolveOutcome.StepTooHigh => FormattableString.Invariant($"step too high (> {PlayerMovementMode.StepUpHeight} m)"),
        ResolveOutcome.SlopeTooSteep => "slope too steep",
        ResolveOutcome.Wall => "wall",
        ResolveOutcome.OuterWall => "outer wall",
        ResolveOutcome.UnloadedAhead => "unloaded land ahead",
        ResolveOutcome.EdgeOfWorld => "edge of the world",
        ResolveOutcome.Moved => "moved",
        ResolveOutcome.Slid => "slid",
        ResolveOutcome.Held => "held (land not loaded)",
        ResolveOutcome.Edge => "held at an edge",
        ResolveOutcome.Ceiling => "head hit",
        _ => outcome.ToString(),
    };

    /// <summary>A leg's jumps, head hits, landings and edge slides, when it had any.</summary>
    private static string DescribeAir((int Jumps, int HeadHits, int Landings, int EdgeSlides) air)
    {
        var parts = new List<string>();
        void Add(int count, string what)
        {
            if (count > 0)
            {
                parts.Add(string.Create(CultureInfo.InvariantCulture, $"{count} × {what}"));
            }
        }

        Add(air.Jumps, "jump");
        Add(air.HeadHits, "head hit");
        Add(air.Landings, "landing");
        Add(air.EdgeSlides, "edge slide");
        return parts.Count == 0 ? "" : "; " + string.Join(", ", parts);
    }

    /// <summary>The engine's outcomes that are refusals (<see cref="ResolveResult.IsRefused"/>), in the engine's order.</summary>
    private static IEnumerable<ResolveOutcome> Refusals =>
        Enum.GetValues<ResolveOutcome>().Where(o => (default(ResolveResult) with { Outcome = o }).IsRefused);

    /// <summary>A landblock as the summary prints it: <c>XXYY</c>.</summary>
    private static string Landblock(uint id) =>
        string.Create(CultureInfo.InvariantCulture, $"{CellIds.LandblockX(id):X2}{CellIds.LandblockY(id):X2}");

    private static IEnumerable<string> Seams(IReadOnlyList<(int Frame, uint CellId)> visits, int first, int last)
    {
        for (int k = first + 1; k <= last; k++)
        {
            if (CellIds.LandblockOf(visits[k].CellId) != CellIds.LandblockOf(visits[k - 1].CellId))
            {
                yield return string.Create(CultureInfo.InvariantCulture, $"0x{Landblock(visits[k - 1].CellId)} -> 0x{Landblock(visits[k].CellId)} at frame {visits[k].Frame}");
            }
        }
    }
}
