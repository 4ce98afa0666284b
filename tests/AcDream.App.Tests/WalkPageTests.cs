using System.Diagnostics;
using System.Globalization;
using System.Text.RegularExpressions;
using AcDream.App.Scenes;
using AcDream.Core.Physics;
using PuppeteerSharp;
using Xunit.Abstractions;

namespace AcDream.App.Tests;

/// <summary>
/// The walk page (<see cref="WalkPage"/>) in Debian's Chromium: it loads from disk with nothing from the network, fast
/// and small enough, and its label at frames chosen from the walk's own record (by setting the timeline, by the arrow
/// keys) says that frame's number, position to the millimetre, cell, outcome and what its steps met.
/// </summary>
[Collection(BrowserCollection.Name)]
public sealed partial class WalkPageTests(WalkPageBrowser browser, ITestOutputHelper log) : IClassFixture<WalkPageBrowser>
{
    /// <summary>The cottage's cellar, entered by a jump through its floor opening.</summary>
    private const uint CottageCellar = 0xA9B40147;

    /// <summary>
    /// Loads the page three times, each in a new tab, from navigation to its first frame drawn: the fastest is under 3 s
    /// (the fastest, so that a test sharing the cores with other test processes measures the page rather than them).
    /// </summary>
    [Fact]
    public async Task Page_OfTheDefaultWalk_LoadsFromDiskInUnderThreeSeconds_UnderThirtyMegabytes_RequestingNothingElse()
    {
        long bytes = new FileInfo(browser.PagePath).Length;
        var loads = new List<TimeSpan>();
        for (int run = 0; run < 3; run++)
        {
            IPage page = await browser.Browser.NewPageAsync();
            var requests = new List<string>();
            page.Request += (_, e) => requests.Add(e.Request.Url);

            var clock = Stopwatch.StartNew();
            await page.GoToAsync(new Uri(browser.PagePath).AbsoluteUri, new NavigationOptions { WaitUntil = [WaitUntilNavigation.Load], Timeout = 30_000 });
            await page.WaitForFunctionAsync("() => window.walkPage?.ready === true", new WaitForFunctionOptions { Timeout = 30_000 });
            await NextPaintAsync(page);
            loads.Add(clock.Elapsed);

            string timing = await page.EvaluateExpressionAsync<string>("(t => `read ${t.responseEnd.toFixed(0)} ms, parsed ${t.domInteractive.toFixed(0)} ms, modules run ${t.domContentLoadedEventStart.toFixed(0)} ms`)(performance.getEntriesByType('navigation')[0])");
            double scriptMs = await page.EvaluateExpressionAsync<double>("window.walkPage.loadMs");
            log.WriteLine($"load {run + 1}: {clock.ElapsedMilliseconds} ms to the first frame drawn ({timing}; the page's script {scriptMs:0} ms)");
            (await page.EvaluateExpressionAsync<int>("window.walkPage.count")).Should().Be(browser.Record.Samples.Count);
            (await Text(page, "message")).Should().BeEmpty("the 3-D view started (WebGL)");
            (await page.EvaluateExpressionAsync<int>("document.querySelectorAll('#view canvas').length")).Should().Be(1);
            requests.Should().OnlyContain(url => url.StartsWith("file:", StringComparison.Ordinal) || url.StartsWith("data:", StringComparison.Ordinal),
                "the page opens from disk: three.js and the walk are inside it");
            await page.CloseAsync();
        }

        log.WriteLine($"page: {bytes} bytes ({bytes / 1048576.0:0.00} MiB), {browser.Record.Samples.Count} frames; fastest load {loads.Min().TotalMilliseconds:0} ms");
        browser.Record.Samples.Count.Should().BeGreaterThan(4900, "the default walk's 4,997 frames");
        bytes.Should().BeLessThan(30L * 1024 * 1024, "a page of 5,000 frames stays under 30 MB");
        loads.Min().Should().BeLessThan(TimeSpan.FromSeconds(3), "a page of 5,000 frames loads in under 3 s");
    }

    [Fact]
    public async Task Timeline_SetToFramesChosenFromTheRecord_LabelSaysEachFramesPositionCellOutcomeAndContacts()
    {
        IReadOnlyList<FrameSample> samples = browser.Record.Samples;
        int[] chosen =
        [
            0,
            Index(s => s.Refusal == ResolveOutcome.Wall),
            Index(s => s.Slide is not null && s.Moved.Met.Wall.Kind == SurfaceKind.CellWall),
            Index(s => s.Slide is not null && s.Moved.Met.Wall.Kind == SurfaceKind.Mover),
            Index(s => !s.IsOnGround),
            Index(s => s.CellId == CottageCellar && s.IsOnGround),
            Index(s => s.Moved.Met.Floor.Kind == SurfaceKind.ObjectFloor),
            samples.Count - 1,
        ];
        (IPage page, _) = await browser.OpenAsync(browser.PagePath);

        foreach (int i in chosen)
        {
            await page.EvaluateFunctionAsync("i => { const t = document.getElementById('timeline'); t.value = String(i); t.dispatchEvent(new Event('input', { bubbles: true })); }", i);
            await LabelShouldDescribe(page, samples[i]);
        }

        await page.CloseAsync();
    }

    [Fact]
    public async Task ArrowKeys_StepOneFrame_ShiftStepsThirty_TheLabelFollows()
    {
        IReadOnlyList<FrameSample> samples = browser.Record.Samples;
        int start = Index(s => s.Refusal == ResolveOutcome.Wall) - 2; // steps into the frames refused at the closed door
        (IPage page, _) = await browser.OpenAsync(browser.PagePath);
        await page.EvaluateFunctionAsync("i => window.walkPage.show(i)", start);

        foreach (int expected in new[] { start + 1, start + 2, start + 3 })
        {
            await page.Keyboard.PressAsync("ArrowRight");
            await LabelShouldDescribe(page, samples[expected]);
        }

        await page.Keyboard.PressAsync("ArrowLeft");
        await LabelShouldDescribe(page, samples[start + 2]);
        await page.Keyboard.DownAsync("Shift");
        await page.Keyboard.PressAsync("ArrowRight");
        await page.Keyboard.UpAsync("Shift");
        await LabelShouldDescribe(page, samples[start + 32]);
        (await page.EvaluateExpressionAsync<string>("document.getElementById('timeline').value")).Should().Be((start + 32).ToString(CultureInfo.InvariantCulture), "the timeline follows the keys");
        await page.Keyboard.PressAsync("End");
        await LabelShouldDescribe(page, samples[^1]);
        await page.CloseAsync();
    }

    [Fact]
    public async Task Frame_InsideTheCottageCellar_IsDrawn_ScreenshotSaved()
    {
        IReadOnlyList<FrameSample> samples = browser.Record.Samples;
        var cellar = samples.Select((s, i) => (s, i)).Where(x => x.s.CellId == CottageCellar && x.s.IsOnGround).Select(x => x.i).ToList();
        cellar.Should().NotBeEmpty("the walk goes down into the cottage's cellar");
        int frame = cellar[cellar.Count / 2];
        (IPage page, _) = await browser.OpenAsync(browser.PagePath);
        await page.EvaluateFunctionAsync("i => { const t = document.getElementById('timeline'); t.value = String(i); t.dispatchEvent(new Event('input', { bubbles: true })); }", frame);
        await LabelShouldDescribe(page, samples[frame]);
        (await Text(page, "cell")).Should().Be("cell 0xA9B40147 (cottage, cellar)");
        await NextPaintAsync(page);

        byte[] png = await page.ScreenshotDataAsync(new ScreenshotOptions { Type = ScreenshotType.Png });
        png.Length.Should().BeGreaterThan(30_000, "a drawn scene, not a blank view");
        string root = TestWorlds.RepositoryRoot();
        Directory.CreateDirectory(Path.Combine(root, "artifacts"));
        await File.WriteAllBytesAsync(Path.Combine(root, "artifacts", "walk-page-cellar.png"), png);
        await File.WriteAllBytesAsync(Path.Combine(root, "docs", "walk-page.png"), png);
        log.WriteLine($"screenshot of frame {samples[frame].Frame}: artifacts/walk-page-cellar.png, docs/walk-page.png ({png.Length} bytes)");
        await page.CloseAsync();
    }

    [Fact]
    public async Task MainJob_WritesThePageBesideTheSvg_SaysWhere_AndThePageShowsItsFrames()
    {
        string folder = Path.Combine(browser.Folder, "main-job");
        var output = new StringWriter();

        MainJob.Run(["--out", folder, "--frames", "300"], output, new StringWriter()).Should().Be(0);

        string page = Path.Combine(folder, "holtburg-walk.html");
        string[] lines = output.ToString().TrimEnd().Split(Environment.NewLine);
        lines[^2..].Should().Equal($"SVG: {Path.Combine(folder, "holtburg-walk.svg")}", $"Page: {page}");
        File.Exists(page).Should().BeTrue();
        (IPage tab, _) = await browser.OpenAsync(page);
        await tab.Keyboard.PressAsync("End");
        (await Text(tab, "frame")).Should().Be("frame 300 of 300", "--frames 300 stops the walk, and the page has its frames");
        await tab.CloseAsync();
    }

    private int Index(Func<FrameSample, bool> match)
    {
        int i = browser.Record.Samples.ToList().FindIndex(s => match(s));
        i.Should().BeGreaterThan(0, "the default walk has such a frame");
        return i;
    }

    /// <summary>The label names <paramref name="sample"/>: frame, position to the millimetre, cell, ground, outcome, floor and wall met.</summary>
    private static async Task LabelShouldDescribe(IPage page, FrameSample sample)
    {
        string because = $"frame {sample.Frame}";
        (await Text(page, "frame")).Should().StartWith($"frame {sample.Frame} of ", because);
        Match position = PositionText().Match(await Text(page, "position"));
        position.Success.Should().BeTrue(because);
        float[] xyz = [.. position.Groups.Values.Skip(1).Select(g => float.Parse(g.Value, CultureInfo.InvariantCulture))];
        xyz[0].Should().BeApproximately(sample.Position.X, 0.00051f, because);
        xyz[1].Should().BeApproximately(sample.Position.Y, 0.00051f, because);
        xyz[2].Should().BeApproximately(sample.Position.Z, 0.00051f, because);
        (await Text(page, "cell")).Should().StartWith($"cell 0x{sample.CellId:X8}", because);
        (await Text(page, "ground")).Should().Be(sample.IsOnGround ? "on the ground" : "in the air", because);
        string outcome = sample.Refusal?.ToString() ?? (sample.Slide is not null ? "Slid" : "Moved");
        (await Text(page, "outcome")).Should().Be($"outcome: {outcome}", because);
        string met = await Text(page, "met");
        ContactShouldBe(met, "floor", sample.Moved.Met.Floor, because);
        ContactShouldBe(met, "wall", sample.Moved.Met.Wall, because);
    }

    /// <summary>The label's "floor: …" or "wall: …" names the contact's kind and id, and its normal to a thousandth.</summary>
    private static void ContactShouldBe(string met, string name, SurfaceContact contact, string because)
    {
        Match m = Regex.Match(met, name + @": (\w+)(?: 0x([0-9A-F]{8}), normal \((-?\d+\.\d{3}), (-?\d+\.\d{3}), (-?\d+\.\d{3})\))?");
        m.Success.Should().BeTrue($"{because}: \"{met}\" names the {name}");
        if (contact.Kind == SurfaceKind.None)
        {
            m.Groups[1].Value.Should().Be("none", because);
            return;
        }

        m.Groups[1].Value.Should().Be(contact.Kind.ToString(), because);
        uint.Parse(m.Groups[2].Value, NumberStyles.HexNumber, CultureInfo.InvariantCulture).Should().Be(contact.Id, because);
        float[] normal = [.. m.Groups.Values.Skip(3).Select(g => float.Parse(g.Value, CultureInfo.InvariantCulture))];
        normal.Should().Equal([contact.Normal.X, contact.Normal.Y, contact.Normal.Z], (a, b) => MathF.Abs(a - b) <= 0.00051f, because);
    }

    private static Task<string> Text(IPage page, string id) => page.EvaluateFunctionAsync<string>("id => document.getElementById(id).textContent", id);

    /// <summary>Waits until the browser has painted twice: the frame shown is drawn.</summary>
    private static Task NextPaintAsync(IPage page) =>
        page.EvaluateExpressionAsync("new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))");

    [GeneratedRegex(@"^\((-?\d+\.\d{3}), (-?\d+\.\d{3}), (-?\d+\.\d{3})\) m$")]
    private static partial Regex PositionText();
}
