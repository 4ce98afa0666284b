using AcDream.App.Scenes;
using AcDream.App.World;
using PuppeteerSharp;

namespace AcDream.App.Tests;

/// <summary>The browser tests' collection: run alone, so their load times are not measured on cores busy with other tests.</summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class BrowserCollection
{
    /// <summary>The collection's name.</summary>
    public const string Name = "browser";
}

/// <summary>
/// The default walk, run once, its page written (<see cref="WalkPage"/>), and Debian's Chromium
/// (<see cref="ChromiumPath"/>) started headless with the flags a machine without network needs, with a fresh profile.
/// Without Chromium every test that uses this fails, naming what to install: the page is tested in a real browser.
/// </summary>
public sealed class WalkPageBrowser : IAsyncLifetime
{
    /// <summary>The system browser: Debian's <c>chromium</c> package (.ci/run installs it).</summary>
    public const string ChromiumPath = "/usr/bin/chromium";

    private readonly string _folder = Path.Combine(Path.GetTempPath(), "acdream-page-tests-" + Guid.NewGuid().ToString("N"));

    /// <summary>The default walk's record.</summary>
    internal WalkRecord Record { get; private set; } = null!;

    /// <summary>The page written for <see cref="Record"/>.</summary>
    public string PagePath => Path.Combine(_folder, "holtburg-walk.html");

    /// <summary>A folder for other pages the tests write.</summary>
    public string Folder => _folder;

    /// <summary>The browser.</summary>
    public IBrowser Browser { get; private set; } = null!;

    /// <inheritdoc/>
    public async Task InitializeAsync()
    {
        Directory.CreateDirectory(_folder);
        Scene scene = SceneReader.ReadDefault();
        HoltburgWorld world = scene.CreateWorld();
        Record = SceneRunner.Run(scene, world);
        await using (var stream = File.Create(PagePath))
        {
            WalkPage.Write(Record, world, stream);
        }

        if (!File.Exists(ChromiumPath))
        {
            throw new InvalidOperationException(
                $"Chromium is not installed at {ChromiumPath}: the walk page is tested in a real browser. Install Debian's package (apt-get install -y chromium); .ci/run does.");
        }

        Browser = await Puppeteer.LaunchAsync(new LaunchOptions
        {
            ExecutablePath = ChromiumPath,
            Headless = true,
            UserDataDir = Path.Combine(_folder, "profile"),
            DefaultViewport = new ViewPortOptions { Width = 1280, Height = 800 },
            Timeout = 60_000,
            Args =
            [
                "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
                "--disable-component-update", "--disable-sync",
                "--enable-unsafe-swiftshader", // WebGL drawn in software: no GPU here, and Chromium no longer falls back to it unasked
            ],
        });
    }

    /// <summary>A new tab with the page at <paramref name="path"/> loaded and ready (its script ran), and the URLs it requested.</summary>
    public async Task<(IPage Page, List<string> Requests)> OpenAsync(string path)
    {
        IPage page = await Browser.NewPageAsync();
        var requests = new List<string>();
        page.Request += (_, e) => requests.Add(e.Request.Url);
        await page.GoToAsync(new Uri(path).AbsoluteUri, new NavigationOptions { WaitUntil = [WaitUntilNavigation.Load], Timeout = 30_000 });
        await page.WaitForFunctionAsync("() => window.walkPage?.ready === true", new WaitForFunctionOptions { Timeout = 30_000 });
        return (page, requests);
    }

    /// <inheritdoc/>
    public async Task DisposeAsync()
    {
        if (Browser is not null)
        {
            await Browser.CloseAsync();
            Browser.Dispose();
        }

        Directory.Delete(_folder, recursive: true);
    }
}
